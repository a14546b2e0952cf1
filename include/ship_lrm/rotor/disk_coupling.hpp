// Rotor disk on a lattice plane (thesis 6.5): area fractions of the cells, force density from the
// harmonic force coefficients, and inflow extraction as mean + linear first harmonics.
//
// Geometry: the disk lies in one cell layer of a grid with spacing dx; cell (i, j) has its centre at
// (i, j) in grid units, and the rotor centre is at (cx, cy). A grid axis x_g points forward and y_g
// to starboard, so a disk point at radius r and azimuth psi (inflow_model.hpp: from aft towards
// starboard) sits at (cx - r cos psi, cy + r sin psi).
//
// Area fractions: the disk is a convex polygon of `polygon_points` (thesis: 360) vertices on radius
// R; each cell whose centre lies between R - sqrt(2)/2 dx and R + sqrt(2)/2 dx is clipped against the
// polygon (Sutherland-Hodgman) and its fraction is the overlap area over the cell area; inside that
// ring the fraction is 1, outside 0.
//
// Force: a cell gets F(psi_cell) * eps * dx^2 / A_disk, with A_disk = sum eps dx^2 (the polygon's
// area, so the mean force is imposed exactly; the thesis divides by pi R^2, 0.005 % different at
// 360 points).
//
// Inflow: eps-weighted least squares of the cell velocities on (1, (r/R) sin psi, (r/R) cos psi). For
// a disk centred in the grid this is the eps-weighted mean and
//   v_sine = sum eps u (r/R) sin psi / sum eps (r/R)^2 sin^2 psi   (likewise cosine),
// which return the coefficients of v(r, psi) = mean + sine (r/R) sin psi + cosine (r/R) cos psi. The
// thesis prints the sum divided by sum eps, which returns a quarter of the coefficient on a full
// disk (mean of (r/R)^2 sin^2 psi is 1/4); this is the inverse of its own reconstruction formula.
#pragma once

#include <array>
#include <cmath>
#include <vector>

#include "ship_lrm/rotor/inflow_model.hpp"

namespace ship_lrm::rotor {

struct DiskCell {
  int i, j;         // grid indices in the disk plane
  double fraction;  // eps, area fraction inside the disk
  double r_over_R, psi;
};

class DiskCoupling {
 public:
  // nx, ny: grid size; (cx, cy): rotor centre in grid units; radius in grid units (R / dx).
  DiskCoupling(int nx, int ny, double cx, double cy, double radius, int polygon_points = 360);

  const std::vector<DiskCell>& cells() const { return cells_; }
  double area() const { return area_; }  // sum of fractions (grid units^2)
  double radius() const { return radius_; }

  // Force per cell (in the harmonics' units times 1/A: force per cell = F(psi) eps / sum eps), one
  // Vec3 per cells() entry.
  std::vector<Vec3> cell_forces(const RotorForceHarmonics& h) const;

  // The same series as the lattice evaluates it (lbm/column_series.hpp, Solver::set_cell_force_columns):
  // kForceColumns per-cell columns, column m of cell c at [m * cells().size() + c]: eps / A (m = 0),
  // eps / A cos(k psi) (m = k), eps / A sin(k psi) (m = kHarmonicOrder + k); set once per lattice.
  static constexpr int kForceColumns = 2 * kHarmonicOrder + 1;
  std::vector<float> force_columns() const;
  // Their coefficients for harmonics h times `scale` (newtons per cell to lattice force density), 3 per
  // column (x y z): what the coupled step hands the lattice every step.
  void force_coefficients(const RotorForceHarmonics& h, double scale, std::vector<float>& out) const;

  // Mean and linear harmonics of a velocity field; velocity(k) returns the velocity of cells()[k].
  template <class VelocityOfCell>
  RotorInflow extract(VelocityOfCell&& velocity) const {
    Vec3 b0 = Vec3::Zero(), bs = Vec3::Zero(), bc = Vec3::Zero();
    for (size_t k = 0; k < cells_.size(); ++k) {
      const DiskCell& c = cells_[k];
      const Vec3 u = velocity(k);
      b0 += c.fraction * u;
      bs += (c.fraction * c.r_over_R * sin_cos_psi_[k][0]) * u;
      bc += (c.fraction * c.r_over_R * sin_cos_psi_[k][1]) * u;
    }
    // weighted least squares for (mean, sine, cosine); on a disk centred in the grid the normal
    // matrix is diagonal and the mean is sum eps u / sum eps, as in the thesis
    RotorInflow out;
    out.mean = g_inv_[0][0] * b0 + g_inv_[0][1] * bs + g_inv_[0][2] * bc;
    out.sine = g_inv_[1][0] * b0 + g_inv_[1][1] * bs + g_inv_[1][2] * bc;
    out.cosine = g_inv_[2][0] * b0 + g_inv_[2][1] * bs + g_inv_[2][2] * bc;
    return out;
  }

 private:
  std::vector<DiskCell> cells_;
  std::vector<std::array<double, 2>> sin_cos_psi_;  // sin psi, cos psi per cell (extract)
  // F(psi) eps / A as a sum over the harmonics' coefficients of per-cell columns (force_columns()'s
  // layout, in double). Contiguous columns let the sum vectorise across the cells.
  std::vector<double> force_basis_;
  double radius_, area_ = 0;
  double g_inv_[3][3] = {};  // inverse of the eps-weighted normal matrix of (1, (r/R) sin, (r/R) cos)
};

// Area of the intersection of a convex polygon (counterclockwise) with the axis-aligned square
// [x0, x1] x [y0, y1] (Sutherland-Hodgman clipping, shoelace area).
double clipped_area(const std::vector<std::array<double, 2>>& polygon, double x0, double x1, double y0, double y1);

}  // namespace ship_lrm::rotor
