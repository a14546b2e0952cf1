#include "ship_lrm/lbm/wall_force.hpp"

namespace ship_lrm::lbm {

std::array<double, 3> wall_force(Solver& solver, const std::vector<char>& body) {
  const Lattice& lat = solver.lattice();
  if (body.size() != lat.cells()) throw ConfigError("wall_force: body mask has the wrong size");
  if (solver.steps_done() % 2 != 0) throw ConfigError("wall_force: call after an even number of steps");
  // After an even number of steps G[i][x] holds f_i(x) after streaming; for a link from wall cell
  // x - c_i it is the population that left x towards the wall and bounced back (halfway
  // bounce-back), so the body receives 2 c_opp(i) f_i = -2 c_i f_i (stationary wall).
  const std::vector<float> g = solver.populations();
  const std::size_t n = lat.cells();
  std::array<double, 3> F{0, 0, 0};
  for (int z = 0; z < lat.nz(); ++z)
    for (int y = 0; y < lat.ny(); ++y)
      for (int x = 0; x < lat.nx(); ++x) {
        const std::size_t c = lat.index(x, y, z);
        if (is_wall(lat.type(x, y, z)) || body[c]) continue;
        for (int i = 1; i < Q; ++i) {
          const int sx = x - d3q19::cx(i), sy = y - d3q19::cy(i), sz = z - d3q19::cz(i);
          if (sx < 0 || sy < 0 || sz < 0 || sx >= lat.nx() || sy >= lat.ny() || sz >= lat.nz()) continue;
          if (!body[lat.index(sx, sy, sz)]) continue;
          const double f = g[static_cast<std::size_t>(i) * n + c] + d3q19::w(i);
          for (int a = 0; a < 3; ++a) F[a] -= 2.0 * d3q19::c(i, a) * f;
        }
      }
  return F;
}

}  // namespace ship_lrm::lbm
