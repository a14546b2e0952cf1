// A plane of the LRM domain through the hub (see domain_slice.hpp).
#include "ship_lrm/lrm/domain_slice.hpp"

#include <algorithm>
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

void add_undisturbed_air(const LrmDomain& domain, DomainSlice& s) {
  s.undisturbed.resize(s.position.size());
  for (std::size_t i = 0; i < s.position.size(); ++i) s.undisturbed[i] = domain.undisturbed_air(s.position[i]);
}

void SliceAverage::add(const DomainSlice& s) {
  if (samples_ == 0) {
    sum_.position = s.position;
    sum_.velocity.assign(s.position.size(), Vec3::Zero());
    sum_.wall.assign(s.position.size(), 0);
    if (!s.undisturbed.empty()) sum_.undisturbed.assign(s.position.size(), Vec3::Zero());
    fluid_.assign(s.position.size(), 0);
    walls_.assign(s.position.size(), 0);
  } else if (s.position.size() != sum_.position.size() || s.undisturbed.size() != sum_.undisturbed.size() ||
             (!s.position.empty() && (s.position.front() != sum_.position.front() || s.position.back() != sum_.position.back()))) {
    throw std::invalid_argument("SliceAverage: a slice of another plane");
  }
  for (std::size_t i = 0; i < s.position.size(); ++i) {
    if (s.wall[i]) {
      ++walls_[i];
      continue;
    }
    ++fluid_[i];
    sum_.velocity[i] += s.velocity[i];
    if (!s.undisturbed.empty()) sum_.undisturbed[i] += s.undisturbed[i];
  }
  sum_.max_mach = std::max(sum_.max_mach, s.max_mach);
  ++samples_;
}

DomainSlice SliceAverage::mean() const {
  DomainSlice m = sum_;
  for (std::size_t i = 0; i < m.position.size(); ++i) {
    const double n = static_cast<double>(std::max(fluid_[i], 1L));
    m.velocity[i] /= n;
    if (!m.undisturbed.empty()) m.undisturbed[i] /= n;
    m.wall[i] = 2 * walls_[i] > samples_ ? 1 : 0;
  }
  return m;
}

}  // namespace ship_lrm::lrm
