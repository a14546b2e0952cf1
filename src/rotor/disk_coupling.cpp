// Rotor disk on a lattice plane: area fractions, cell forces (see disk_coupling.hpp).
#include "ship_lrm/rotor/disk_coupling.hpp"

#include <Eigen/Dense>
#include <array>
#include <cmath>
#include <stdexcept>

#include "ship_lrm/lbm/column_series.hpp"

namespace ship_lrm::rotor {
namespace {

using Pt = std::array<double, 2>;

// Keep the part of `poly` with a * x + b * y <= c.
std::vector<Pt> clip(const std::vector<Pt>& poly, double a, double b, double c) {
  std::vector<Pt> out;
  const size_t n = poly.size();
  for (size_t k = 0; k < n; ++k) {
    const Pt& p = poly[k];
    const Pt& q = poly[(k + 1) % n];
    const double dp = a * p[0] + b * p[1] - c, dq = a * q[0] + b * q[1] - c;
    if (dp <= 0) out.push_back(p);
    if ((dp < 0 && dq > 0) || (dp > 0 && dq < 0)) {
      const double t = dp / (dp - dq);
      out.push_back({p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])});
    }
  }
  return out;
}

}  // namespace

double clipped_area(const std::vector<std::array<double, 2>>& polygon, double x0, double x1, double y0, double y1) {
  std::vector<Pt> p = clip(polygon, 1, 0, x1);
  p = clip(p, -1, 0, -x0);
  p = clip(p, 0, 1, y1);
  p = clip(p, 0, -1, -y0);
  double a = 0;
  for (size_t k = 0; k < p.size(); ++k) {
    const Pt& u = p[k];
    const Pt& v = p[(k + 1) % p.size()];
    a += u[0] * v[1] - v[0] * u[1];
  }
  return 0.5 * std::abs(a);
}

DiskCoupling::DiskCoupling(int nx, int ny, double cx, double cy, double radius, int polygon_points) : radius_(radius) {
  if (!(radius > 1.0)) throw std::invalid_argument("rotor disk: the radius must span more than one cell");
  if (polygon_points < 8) throw std::invalid_argument("rotor disk: at least 8 polygon points");
  if (cx - radius < -0.5 || cx + radius > nx - 0.5 || cy - radius < -0.5 || cy + radius > ny - 0.5)
    throw std::invalid_argument("rotor disk: the disk does not fit in the grid");
  std::vector<Pt> poly(polygon_points);
  for (int k = 0; k < polygon_points; ++k) {
    const double a = 2.0 * M_PI * k / polygon_points;
    poly[k] = {cx + radius * std::cos(a), cy + radius * std::sin(a)};
  }
  const double ring = 0.5 * std::sqrt(2.0);
  const int i0 = std::max(0, static_cast<int>(std::floor(cx - radius - 1))),
            i1 = std::min(nx - 1, static_cast<int>(std::ceil(cx + radius + 1)));
  const int j0 = std::max(0, static_cast<int>(std::floor(cy - radius - 1))),
            j1 = std::min(ny - 1, static_cast<int>(std::ceil(cy + radius + 1)));
  for (int j = j0; j <= j1; ++j)
    for (int i = i0; i <= i1; ++i) {
      const double dx = i - cx, dy = j - cy;
      const double r = std::hypot(dx, dy);
      double eps;
      if (r < radius - ring)
        eps = 1.0;
      else if (r > radius + ring)
        eps = 0.0;
      else
        eps = clipped_area(poly, i - 0.5, i + 0.5, j - 0.5, j + 0.5);
      if (eps <= 0) continue;
      DiskCell c{i, j, eps, r / radius, std::atan2(dy, -dx)};
      cells_.push_back(c);
      area_ += eps;
    }
  const std::size_t n = cells_.size();
  force_basis_.assign(kForceColumns * n, 0.0);
  for (std::size_t c = 0; c < n; ++c) {
    const double psi = cells_[c].psi, w = cells_[c].fraction / area_;
    sin_cos_psi_.push_back({std::sin(psi), std::cos(psi)});
    force_basis_[c] = w;
    for (int k = 1; k <= kHarmonicOrder; ++k) {
      force_basis_[k * n + c] = w * std::cos(k * psi);
      force_basis_[(kHarmonicOrder + k) * n + c] = w * std::sin(k * psi);
    }
  }
  Eigen::Matrix3d g = Eigen::Matrix3d::Zero();
  for (const DiskCell& c : cells_) {
    const Eigen::Vector3d basis(1.0, c.r_over_R * std::sin(c.psi), c.r_over_R * std::cos(c.psi));
    g += c.fraction * basis * basis.transpose();
  }
  const Eigen::Matrix3d gi = g.inverse();
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) g_inv_[a][b] = gi(a, b);
}

namespace {
// The harmonics as the columns' coefficients (force_columns()'s order), 3 per column.
template <class T>
void pack_coefficients(const RotorForceHarmonics& h, double scale, std::vector<T>& out) {
  out.resize(3 * DiskCoupling::kForceColumns);
  for (int m = 0; m < DiskCoupling::kForceColumns; ++m) {
    const Vec3& coef = m <= kHarmonicOrder ? h.cos[m] : h.sin[m - kHarmonicOrder];
    for (int d = 0; d < 3; ++d) out[3 * m + d] = static_cast<T>(scale * coef[d]);
  }
}
}  // namespace

std::vector<Vec3> DiskCoupling::cell_forces(const RotorForceHarmonics& h) const {
  // F(psi) of thesis 6.5: F = c_0 + sum_k c_k cos(k psi) + s_k sin(k psi), times eps / A
  const std::size_t n = cells_.size();
  std::vector<double> coef, f(3 * n);
  pack_coefficients(h, 1.0, coef);
  lbm::column_series(force_basis_.data(), n, 0, n, kForceColumns, coef.data(), f.data(), n);
  std::vector<Vec3> out(n);
  for (std::size_t c = 0; c < n; ++c) out[c] = Vec3(f[c], f[n + c], f[2 * n + c]);
  return out;
}

std::vector<float> DiskCoupling::force_columns() const { return std::vector<float>(force_basis_.begin(), force_basis_.end()); }

void DiskCoupling::force_coefficients(const RotorForceHarmonics& h, double scale, std::vector<float>& out) const {
  pack_coefficients(h, scale, out);
}

}  // namespace ship_lrm::rotor
