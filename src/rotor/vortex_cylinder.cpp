// Vortex-cylinder wake of a uniformly loaded actuator disk (see vortex_cylinder.hpp).
#include "ship_lrm/rotor/vortex_cylinder.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace ship_lrm::rotor {

Vec3 vortex_ring_velocity(double radius, double gamma, const Vec3& p, double core2) {
  const double rho = std::hypot(p.x(), p.y()), z = p.z();
  const double outer2 = (rho + radius) * (rho + radius) + z * z + core2;  // squared distance to the far side
  const double inner2 = (radius - rho) * (radius - rho) + z * z + core2;  // to the near side
  const double m = 4.0 * radius * rho / outer2;                           // parameter k^2, below 1 with a core
  const double k = std::sqrt(std::min(m, 1.0 - 1e-15));
  const double K = std::comp_ellint_1(k), E = std::comp_ellint_2(k);
  const double a = gamma / (2.0 * M_PI * std::sqrt(outer2));
  const double uz = a * (K + (radius * radius - rho * rho - z * z) / inner2 * E);
  if (rho < 1e-12 * radius) return Vec3(0, 0, uz);
  const double ur = a * z / rho * (-K + (radius * radius + rho * rho + z * z) / inner2 * E);
  return Vec3(ur * p.x() / rho, ur * p.y() / rho, uz);
}

namespace {
// Momentum theory with the wake carried by air + v e_z: v |air + v e_z| = v_h^2 (Glauert); Newton from
// the larger of v_h and the edgewise estimate.
double momentum_induced(double thrust, double density, double radius, const Vec3& air) {
  const double vh2 = thrust / (2.0 * density * M_PI * radius * radius);
  const double inplane2 = air.x() * air.x() + air.y() * air.y();
  double v = std::max(std::sqrt(vh2), vh2 / std::sqrt(inplane2 + 1e-300));
  v = std::min(v, std::sqrt(vh2) * 1e3);
  for (int i = 0; i < 100; ++i) {
    const double w = air.z() + v, s = std::sqrt(inplane2 + w * w);
    const double f = v * s - vh2, df = s + v * w / s;
    if (!(df > 0)) break;
    const double dv = f / df;
    v -= dv;
    if (std::abs(dv) < 1e-12 * (1.0 + std::abs(v))) {
      if (v > 0) return v;
      break;
    }
  }
  throw std::invalid_argument("vortex-cylinder wake: momentum theory found no induced velocity for this descent (vortex-ring state)");
}
}  // namespace

VortexCylinderWake::VortexCylinderWake(double radius, double thrust, double density, const Vec3& air, double core, double spacing,
                                       double length)
    : radius_(radius) {
  if (!(radius > 0) || !(thrust > 0) || !(density > 0) || !air.allFinite() || !(core >= 0) || !(spacing > 0) || !(length > spacing))
    throw std::invalid_argument("vortex-cylinder wake: needs radius, thrust, density, spacing > 0, core >= 0, a finite air velocity");
  v_ = momentum_induced(thrust, density, radius, air);
  const Vec3 wake = air + Vec3(0, 0, v_);
  if (!(wake.norm() > 1e-6 * std::sqrt(thrust / (2.0 * density * M_PI * radius * radius))))
    throw std::invalid_argument("vortex-cylinder wake: the wake does not move away from the disk (vortex-ring state)");
  d_ = wake / wake.norm();
  ds_ = spacing * radius;
  rings_ = static_cast<int>(std::ceil(length / spacing));
  core2_ = std::max(core, ds_) * std::max(core, ds_);
}

Vec3 VortexCylinderWake::velocity(const Vec3& p) const {
  // ring k at s = (k + 1/2) ds along the axis d. The edge sheds circulation at the rate Delta p / rho =
  // T / (rho A) (the potential jump across the disk), and the rings move |V_w| per unit time, so the
  // circulation per unit length of axis is T / (rho A |V_w|) = 2 v by momentum theory.
  const double gamma_ds = 2.0 * v_ * ds_;
  Vec3 u = Vec3::Zero();
  for (int k = 0; k < rings_; ++k) u += vortex_ring_velocity(radius_, gamma_ds, p - (k + 0.5) * ds_ * d_, core2_);
  return u;
}

}  // namespace ship_lrm::rotor
