// Vortex-cylinder wake of a uniformly loaded actuator disk (see vortex_cylinder.hpp).
#include "ship_lrm/rotor/vortex_cylinder.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "ship_lrm/rotor/momentum_theory.hpp"

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

VortexCylinderWake::VortexCylinderWake(double radius, double thrust, double density, const Vec3& air, double core, double spacing,
                                       double length)
    : radius_(radius) {
  if (!(radius > 0) || !(thrust > 0) || !(density > 0) || !air.allFinite() || !(core >= 0) || !(spacing > 0) || !(length > spacing))
    throw std::invalid_argument("vortex-cylinder wake: needs radius, thrust, density, spacing > 0, core >= 0, a finite air velocity");
  try {
    v_ = momentum_induced_velocity(thrust, density, radius, std::hypot(air.x(), air.y()), air.z());
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("vortex-cylinder wake: ") + e.what());
  }
  const Vec3 wake = air + Vec3(0, 0, v_);
  if (!(wake.norm() > 1e-6 * hover_induced_velocity(thrust, density, radius)))
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
  for (int k = 0; k < rings_; ++k) {
    const Vec3 c = (k + 0.5) * ds_ * d_;
    if (c.z() >= ground_) continue;  // cut at the ground
    u += vortex_ring_velocity(radius_, gamma_ds, p - c, core2_);
    if (ground_ < std::numeric_limits<double>::infinity()) {
      // the mirror image: a ring in the plane z = 2 g - c_z, circulating the other way
      const Vec3 image(c.x(), c.y(), 2.0 * ground_ - c.z());
      u += vortex_ring_velocity(radius_, -gamma_ds, p - image, core2_);
    }
  }
  return u;
}

void VortexCylinderWake::set_ground(double height) {
  if (!(height > 0)) throw std::invalid_argument("vortex-cylinder wake: the ground must lie below the disk (height > 0 m)");
  ground_ = height;
}

}  // namespace ship_lrm::rotor
