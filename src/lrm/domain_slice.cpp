// A plane of the LRM domain through the hub (see domain_slice.hpp).
#include "ship_lrm/lrm/domain_slice.hpp"

#include <cmath>
#include <stdexcept>

#include "ship_lrm/lbm/cell_types.hpp"

namespace ship_lrm::lrm {

DomainSlice domain_slice(LrmDomain& domain, int normal) {
  if (normal < 0 || normal > 2) throw std::invalid_argument("domain_slice: normal must be 0, 1 or 2");
  const lbm::Lattice& lat = domain.solver().lattice();
  const int n[3] = {lat.nx(), lat.ny(), lat.nz()};
  const int a = (normal + 1) % 3, b = (normal + 2) % 3;
  // the hub's layer: the cell whose centre is nearest to the hub along the normal
  const Vec3 origin = domain.position(0, 0, 0);
  const int layer = static_cast<int>(std::lround(-origin[normal] / domain.units().dx()));
  std::vector<std::uint32_t> cells;
  DomainSlice s;
  for (int v = 0; v < n[b]; ++v)
    for (int u = 0; u < n[a]; ++u) {
      int ijk[3];
      ijk[normal] = layer;
      ijk[a] = u;
      ijk[b] = v;
      cells.push_back(static_cast<std::uint32_t>(lat.index(ijk[0], ijk[1], ijk[2])));
      s.position.push_back(domain.position(ijk[0], ijk[1], ijk[2]));
      s.wall.push_back(lbm::is_wall(lat.type(ijk[0], ijk[1], ijk[2])) ? 1 : 0);
    }
  const std::vector<float> u = domain.solver().velocities(cells);
  const double scale = domain.units().dx() / domain.units().dt();
  const double cs = 1.0 / std::sqrt(3.0);
  s.velocity.resize(cells.size());
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const Vec3 lu(u[3 * i], u[3 * i + 1], u[3 * i + 2]);
    s.velocity[i] = lu * scale;
    if (!s.wall[i]) s.max_mach = std::max(s.max_mach, std::isfinite(lu.norm()) ? lu.norm() / cs : INFINITY);
  }
  return s;
}

}  // namespace ship_lrm::lrm
