// Open-boundary velocities from a gridded velocity field that lives in another frame: the ship-wake
// table feeding the LRM's faces (thesis 5.2, 6.3). Written once for the host and the device
// (hd.hpp): WakeTable::sample and LrmDomain's host path call these functions, and so does the CUDA
// backend's feed kernel, which computes the face values where the faces live, so that only the pose
// crosses the bus per refresh (docs/design.md, "Feeding the LRM from a wake table").
//
// The field: two time frames of a window of a regular grid (spacing h, grid point (0, 0, 0) at
// `origin`), interpolated trilinearly in space and linearly in time; outside the grid the free stream.
// The domain: cell (i, j, k) sits at r = ((i, j, k) - centre) dx from the hub, in the domain's axes;
// in the grid's frame at hub + R r. The air relative to the hub in the domain's axes is
// R^T (u(hub + R r) - hub_velocity), and a face of a domain turning at omega imposes
// (air - omega x r) in lattice units (the rotating-frame velocity; design.md, "The domain moves with the rotorcraft").
#pragma once
#include <cstddef>
#include <cstdint>

#include "ship_lrm/lbm/hd.hpp"

namespace ship_lrm::lbm {

// One time frame of a window of the grid: the points [lo, lo + n) (x, y, z of the whole grid), values
// `u` with 3 floats per point, x fastest. A window with n = 0 is empty (the domain lies outside the grid).
struct GridWindowView {
  int lo[3] = {0, 0, 0};
  int n[3] = {0, 0, 0};
  const float* u = nullptr;
};

// Where the grid is, where the domain is in it, and how the domain moves (a plain struct: kernel argument).
struct GridFeed {
  double origin[3] = {0, 0, 0};  // m, grid point (0, 0, 0)
  double spacing = 1;            // m
  int shape[3] = {0, 0, 0};      // points of the whole grid (x, y, z)
  double weight1 = 0;            // weight of the second frame (linear in time); the first gets 1 - weight1
  float free_stream[3] = {0, 0, 0};
  double hub[3] = {0, 0, 0};                         // m, grid frame
  double rotation[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};  // domain axes -> grid axes, row-major
  double hub_velocity[3] = {0, 0, 0};                // m/s, grid frame
  double omega[3] = {0, 0, 0};                       // rad/s, the domain's angular velocity, domain axes
  double to_lattice = 1;                             // dt / dx
  double dx = 1;                                     // m
  double centre = 0;                                 // cell coordinate of the hub
};

// True when grid coordinates g lie inside the grid (the closed box of its points).
SHIP_LRM_HD bool grid_inside(const double g[3], const int shape[3]) {
  for (int d = 0; d < 3; ++d)
    if (!(g[d] >= 0.0 && g[d] <= shape[d] - 1)) return false;
  return true;
}

// The grid cell (lower corner i, whole-grid index) and the fractions fr in it of grid coordinates g
// inside the grid; the last point of an axis belongs to the cell before it.
SHIP_LRM_HD void grid_cell(const double g[3], const int shape[3], int i[3], double fr[3]) {
  for (int d = 0; d < 3; ++d) {
    i[d] = static_cast<int>(g[d]) < shape[d] - 2 ? static_cast<int>(g[d]) : shape[d] - 2;
    fr[d] = g[d] - i[d];
  }
}

// acc[0 .. nv) += wt x the trilinear interpolation of `values` (nv per point, x fastest) of a window
// whose first point is lo and size n, in the grid cell i (whole-grid index) at fractions fr.
SHIP_LRM_HD void accumulate_trilinear(const float* values, int nv, const int lo[3], const int n[3], const int i[3], const double fr[3],
                                      double wt, double* acc) {
  const int x = i[0] - lo[0], y = i[1] - lo[1], z = i[2] - lo[2];
  for (int c = 0; c < 8; ++c) {
    const int dx = c & 1, dy = (c >> 1) & 1, dz = (c >> 2) & 1;
    const double wc = wt * (dx ? fr[0] : 1 - fr[0]) * (dy ? fr[1] : 1 - fr[1]) * (dz ? fr[2] : 1 - fr[2]);
    const std::size_t k =
        static_cast<std::size_t>(x + dx) + static_cast<std::size_t>(n[0]) * (y + dy + static_cast<std::size_t>(n[1]) * (z + dz));
    for (int a = 0; a < nv; ++a) acc[a] += wc * values[nv * k + a];
  }
}

// The field's velocity at point p (m, grid frame) at the feed's time: trilinear in space, linear in
// time between the two frames, rounded to float as the table stores it; the free stream outside.
SHIP_LRM_HD void grid_velocity(const GridFeed& f, const GridWindowView& w0, const GridWindowView& w1, const double p[3], float u[3]) {
  double g[3];
  for (int d = 0; d < 3; ++d) g[d] = (p[d] - f.origin[d]) / f.spacing;
  if (!grid_inside(g, f.shape)) {
    for (int d = 0; d < 3; ++d) u[d] = f.free_stream[d];
    return;
  }
  int i[3];
  double fr[3], acc[3] = {0, 0, 0};
  grid_cell(g, f.shape, i, fr);
  if (1.0 - f.weight1 != 0.0) accumulate_trilinear(w0.u, 3, w0.lo, w0.n, i, fr, 1.0 - f.weight1, acc);
  if (f.weight1 != 0.0) accumulate_trilinear(w1.u, 3, w1.lo, w1.n, i, fr, f.weight1, acc);
  for (int d = 0; d < 3; ++d) u[d] = static_cast<float>(acc[d]);
}

// Position of cell (x, y, z) relative to the hub (m, domain axes).
SHIP_LRM_HD void feed_cell_position(const GridFeed& f, int x, int y, int z, double r[3]) {
  r[0] = (x - f.centre) * f.dx;
  r[1] = (y - f.centre) * f.dx;
  r[2] = (z - f.centre) * f.dx;
}

// The field's air relative to the hub at r (m, domain axes from the hub), in the domain's axes (m/s).
SHIP_LRM_HD void grid_air(const GridFeed& f, const GridWindowView& w0, const GridWindowView& w1, const double r[3], double air[3]) {
  const double* R = f.rotation;
  double p[3];
  for (int a = 0; a < 3; ++a) p[a] = f.hub[a] + (R[3 * a] * r[0] + R[3 * a + 1] * r[1] + R[3 * a + 2] * r[2]);
  float u[3];
  grid_velocity(f, w0, w1, p, u);
  double rel[3];
  for (int a = 0; a < 3; ++a) rel[a] = static_cast<double>(u[a]) - f.hub_velocity[a];
  for (int a = 0; a < 3; ++a) air[a] = R[a] * rel[0] + R[3 + a] * rel[1] + R[6 + a] * rel[2];  // R^T rel
}

// Face velocity in lattice units of a domain turning at omega (rad/s, domain axes): (air - omega x r) dt/dx.
SHIP_LRM_HD void face_lattice_velocity(const double air[3], const double omega[3], const double r[3], double to_lattice, double u[3]) {
  const double w[3] = {omega[1] * r[2] - omega[2] * r[1], omega[2] * r[0] - omega[0] * r[2], omega[0] * r[1] - omega[1] * r[0]};
  for (int a = 0; a < 3; ++a) u[a] = (air[a] - w[a]) * to_lattice;
}

// The 4th boundary value of an impedance outlet: the outward normal change of its reference velocity
// (old -> new), added to a change not yet stepped (see Solver::set_boundary_values). normal: the
// boundary normal code (axis << 1 | positive side).
SHIP_LRM_HD float impedance_reference_shift(float pending, std::uint8_t normal, const float* old_u, const float* new_u) {
  const int axis = normal >> 1;
  const float sgn = (normal & 1) ? 1.0f : -1.0f;
  return pending + sgn * (component(new_u, axis) - component(old_u, axis));
}

// One open-boundary cell (x, y, z) fed by the grid (its 4 boundary values at `value`): a velocity inlet
// takes the face velocity, an impedance outlet takes it as its reference and adds the reference's
// outward normal change to its 4th value (see Solver::set_boundary_values). The CUDA feed kernel and
// Solver::feed_faces_from_grid's host loop both call it.
SHIP_LRM_HD void feed_boundary_cell(const GridFeed& f, const GridWindowView& w0, const GridWindowView& w1, bool impedance,
                                    std::uint8_t normal, int x, int y, int z, float* value) {
  double r[3], air[3], u[3];
  feed_cell_position(f, x, y, z, r);
  grid_air(f, w0, w1, r, air);
  face_lattice_velocity(air, f.omega, r, f.to_lattice, u);
  float nu[3];
  for (int a = 0; a < 3; ++a) nu[a] = static_cast<float>(u[a]);
  if (impedance) value[3] = impedance_reference_shift(value[3], normal, value, nu);
  for (int a = 0; a < 3; ++a) value[a] = nu[a];
}

}  // namespace ship_lrm::lbm
