// The ship and the sea on a grid of nodes (see ship_voxels.hpp).
#include "ship_lrm/wake/ship_voxels.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "ship_lrm/lbm/grid_feed.hpp"

namespace ship_lrm::wake {

std::array<Vec3, 8> hull_box(const ShipGeometry& ship) {
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const auto& t : ship.mesh())
    for (const auto& v : t.v) {
      lo = lo.cwiseMin(v);
      hi = hi.cwiseMax(v);
    }
  std::array<Vec3, 8> c;
  for (int k = 0; k < 8; ++k) c[k] = Vec3(k & 1 ? hi.x() : lo.x(), k & 2 ? hi.y() : lo.y(), k & 4 ? hi.z() : lo.z());
  return c;
}

std::vector<std::uint8_t> voxelise_ship(const NodeGrid& grid, const ShipGeometry& ship, const ShipMotion& motion,
                                        const std::array<Vec3, 8>& box, double t) {
  std::vector<std::uint8_t> owner(grid.cells(), kFluidNode);
  const double water = ship.datum().waterline;
  for (int k = 0; k < grid.nz; ++k)
    if (grid.position(0, 0, k).z() > water)
      for (int j = 0; j < grid.ny; ++j)
        for (int i = 0; i < grid.nx; ++i) owner[grid.index(i, j, k)] = kSeaNode;
  // the hull's box at time t, in cells
  Vec3 lo = Vec3::Constant(1e300), hi = -lo;
  for (const Vec3& c : box) {
    const Vec3 g = (motion.position(c, t) - grid.origin) / grid.dx;
    lo = lo.cwiseMin(g);
    hi = hi.cwiseMax(g);
  }
  const ShipPlacement place = motion.placement(t);
  for (int k = std::max(0, int(std::floor(lo.z())) - 1); k <= std::min(grid.nz - 1, int(std::ceil(hi.z())) + 1); ++k)
    for (int j = std::max(0, int(std::floor(lo.y())) - 1); j <= std::min(grid.ny - 1, int(std::ceil(hi.y())) + 1); ++j)
      for (int i = std::max(0, int(std::floor(lo.x())) - 1); i <= std::min(grid.nx - 1, int(std::ceil(hi.x())) + 1); ++i) {
        const std::size_t n = grid.index(i, j, k);
        if (owner[n] != kFluidNode) continue;
        if (ship.inside(place.to_body(grid.position(i, j, k)))) owner[n] = kShipNode;
      }
  return owner;
}

lbm::WallMotion hull_wall_motion(const NodeGrid& grid, const ShipMotion& motion, double t, double dt) {
  lbm::WallMotion w;
  const Vec3 v = motion.centre_velocity(t) * dt / grid.dx, om = motion.omega(t) * dt;
  const Vec3 c = (motion.position(motion.centre(), t) - grid.origin) / grid.dx;
  for (int d = 0; d < 3; ++d) {
    w.v[d] = static_cast<float>(v[d]);
    w.omega[d] = static_cast<float>(om[d]);
    w.centre[d] = static_cast<float>(c[d]);
  }
  return w;
}

double hull_displacement(const ShipMotion& motion, const std::array<Vec3, 8>& box, double t0, double t1) {
  double moved = 0;
  for (const Vec3& c : box) moved = std::max(moved, (motion.position(c, t1) - motion.position(c, t0)).norm());
  return moved;
}

bool fluid_velocity_at(const NodeGrid& grid, const std::vector<std::uint8_t>& owner, const float* u, double scale, const Vec3& p,
                       std::array<double, 3>& out) {
  const double g[3] = {(p.x() - grid.origin.x()) / grid.dx, (p.y() - grid.origin.y()) / grid.dx, (p.z() - grid.origin.z()) / grid.dx};
  const int shape[3] = {grid.nx, grid.ny, grid.nz};
  if (!lbm::grid_inside(g, shape)) return false;
  if (owner[grid.index(static_cast<int>(std::lround(g[0])), static_cast<int>(std::lround(g[1])), static_cast<int>(std::lround(g[2])))] !=
      kFluidNode)
    return false;
  int i[3];
  double fr[3];
  lbm::grid_cell(g, shape, i, fr);
  out = {0, 0, 0};
  for (int c = 0; c < 8; ++c) {
    const int dx = c & 1, dy = (c >> 1) & 1, dz = (c >> 2) & 1;
    const std::size_t n = grid.index(i[0] + dx, i[1] + dy, i[2] + dz);
    if (owner[n] != kFluidNode) continue;  // a wall corner: the air at rest on it (no slip, mean frame)
    const double w = scale * (dx ? fr[0] : 1 - fr[0]) * (dy ? fr[1] : 1 - fr[1]) * (dz ? fr[2] : 1 - fr[2]);
    for (int a = 0; a < 3; ++a) out[a] += w * u[3 * n + a];
  }
  return true;
}

}  // namespace ship_lrm::wake
