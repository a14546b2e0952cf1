// Cell and domain-face types of the lattice (thesis 6.1.3 boundary conditions).
#pragma once

#include <cstdint>

#include "ship_lrm/lbm/hd.hpp"

namespace ship_lrm::lbm {

// Per-cell type, one byte per cell.
enum class CellType : std::uint8_t {
  Fluid = 0,
  Wall = 1,             // no-slip bounce-back wall (halfway, Ladd 1994)
  SlipWall = 2,         // specular (slip) wall where it forms a plane; bounce-back at edges/corners
  MovingWall = 3,       // no-slip wall moving with a rigid-body velocity; tag = index in the wall table
  VelocityInlet = 4,    // open boundary cell: prescribed velocity, FD reconstruction (Latt et al. 2008)
  PressureOutlet = 5,   // open boundary cell: prescribed density, FD reconstruction
  ImpedanceOutlet = 6,  // open boundary cell: non-reflecting impedance outlet (thesis eq. 6.15)
};

// Bit set in the stored type byte of fluid cells that have a wall, a periodic wrap or the domain
// edge among their 18 neighbours: they take the general (checked) streaming path.
constexpr std::uint8_t kGeneralBit = 0x80;

SHIP_LRM_HD constexpr bool is_wall(CellType t) { return t == CellType::Wall || t == CellType::SlipWall || t == CellType::MovingWall; }
SHIP_LRM_HD constexpr bool is_open_boundary(CellType t) {
  return t == CellType::VelocityInlet || t == CellType::PressureOutlet || t == CellType::ImpedanceOutlet;
}

// Behaviour of one face of the box domain. Faces are numbered -x, +x, -y, +y, -z, +z (0..5).
enum class FaceType : std::uint8_t {
  Wall = 0,             // no-slip bounce-back half a cell outside the outermost layer
  SlipWall = 1,         // slip (specular) wall half a cell outside the outermost layer
  MovingWall = 2,       // no-slip wall with a tangential velocity (Couette lid)
  Periodic = 3,         // wraps to the opposite face (both must be periodic)
  VelocityInlet = 4,    // outermost layer holds velocity-inlet cells
  PressureOutlet = 5,   // outermost layer holds pressure-outlet cells
  ImpedanceOutlet = 6,  // outermost layer holds impedance-outlet cells
};

const char* to_string(FaceType t);
const char* to_string(CellType t);

// Rigid-body motion of a moving wall (lattice units; centre in cell coordinates):
// u(p) = v + omega x (p - centre).
struct WallMotion {
  float v[3] = {0, 0, 0};
  float omega[3] = {0, 0, 0};
  float centre[3] = {0, 0, 0};
  // rho_w of the moving-wall term (Ladd 1994, eq. 3.2) = 1 + local_density (rho - 1), rho the
  // density of the fluid cell at the link: 0 takes the reference density, 1 the fluid's own. The
  // fluid's own keeps a stream of any density passing through a wall that moves with it along its
  // normal as it is (with 1, such a wall takes out u_n where the stream brings rho u_n).
  float local_density = 0.0f;
};

// u(p) of rigid motion m at point p (cell coordinates).
SHIP_LRM_HD void rigid_velocity(const WallMotion& m, float px, float py, float pz, float u[3]) {
  const float r[3] = {px - m.centre[0], py - m.centre[1], pz - m.centre[2]};
  u[0] = m.v[0] + m.omega[1] * r[2] - m.omega[2] * r[1];
  u[1] = m.v[1] + m.omega[2] * r[0] - m.omega[0] * r[2];
  u[2] = m.v[2] + m.omega[0] * r[1] - m.omega[1] * r[0];
}

// Wall index of a held cell (Lattice::set_held) that is held at rest.
constexpr std::uint8_t kHeldWallAtRest = 255;

}  // namespace ship_lrm::lbm
