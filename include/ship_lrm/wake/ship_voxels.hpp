// The ship and the sea on a regular grid of lattice nodes in the ship's mean frame: which node is
// fluid, sea or ship at a time, and the hull's rigid motion in that grid's lattice units. Shared by
// the wake domain and its fine region, so that both levels see the same ship the same way.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "ship_lrm/lbm/lattice.hpp"
#include "ship_lrm/wake/ship_geometry.hpp"
#include "ship_lrm/wake/ship_motion.hpp"

namespace ship_lrm::wake {

// Node (i, j, k) sits at origin + (i, j, k) dx (ship's mean frame: x forward, y starboard, z down).
struct NodeGrid {
  Vec3 origin = Vec3::Zero();
  double dx = 1;
  int nx = 0, ny = 0, nz = 0;
  std::size_t cells() const { return static_cast<std::size_t>(nx) * ny * nz; }
  std::size_t index(int i, int j, int k) const {
    return static_cast<std::size_t>(i) + static_cast<std::size_t>(nx) * (static_cast<std::size_t>(j) + static_cast<std::size_t>(ny) * k);
  }
  Vec3 position(int i, int j, int k) const { return origin + Vec3(i, j, k) * dx; }
};

// What a node holds.
constexpr std::uint8_t kFluidNode = 0, kSeaNode = 1, kShipNode = 2;

// The corners of the box of the ship's mesh (ship frame).
std::array<Vec3, 8> hull_box(const ShipGeometry& ship);

// Every node's owner at time t: sea below the waterline (z > waterline), ship where the hull is (its
// box at t, then the ship's inside test), fluid elsewhere.
std::vector<std::uint8_t> voxelise_ship(const NodeGrid& grid, const ShipGeometry& ship, const ShipMotion& motion,
                                        const std::array<Vec3, 8>& box, double t);

// The hull's rigid motion at time t in the grid's lattice units (time step dt in s).
lbm::WallMotion hull_wall_motion(const NodeGrid& grid, const ShipMotion& motion, double t, double dt);

// The velocity at point p (m/s: lattice velocities `u`, 3 per node, times `scale` = dx / dt),
// trilinear between the grid's nodes, a wall node of p's cell counted as air at rest on it (no slip
// in the mean frame: within one cell of a moving hull this leaves out the hull's own velocity); false
// outside the grid or when the node nearest p is not fluid (a probe in the ship or the sea).
bool fluid_velocity_at(const NodeGrid& grid, const std::vector<std::uint8_t>& owner, const float* u, double scale, const Vec3& p,
                       std::array<double, 3>& out);

// How far (m) the hull's box has moved between times t0 and t1: the largest corner displacement.
double hull_displacement(const ShipMotion& motion, const std::array<Vec3, 8>& box, double t0, double t1);

}  // namespace ship_lrm::wake
