// Vortex-cylinder wake of a uniformly loaded actuator disk (see vortex_cylinder.hpp).
#include "ship_lrm/rotor/vortex_cylinder.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "ship_lrm/rotor/momentum_theory.hpp"

namespace ship_lrm::rotor {

void complete_elliptic_integrals(double m, double& K, double& E) {
  if (!(m >= 0 && m < 1)) throw std::invalid_argument("complete elliptic integrals: the parameter m must lie in [0, 1)");
  // the arithmetic-geometric mean (Abramowitz & Stegun 1964, 17.6.3 - 17.6.4): a_0 = 1, b_0 = sqrt(1 - m),
  // c_0^2 = m; K = pi / (2 a_N), E = K (1 - sum_n 2^(n-1) c_n^2); quadratic convergence
  double a = 1.0, b = std::sqrt(1.0 - m), sum = 0.5 * m, weight = 0.5;
  for (int n = 0; n < 40 && a - b > 1e-15 * a; ++n) {
    const double c = 0.5 * (a - b);
    const double next_b = std::sqrt(a * b);
    a = 0.5 * (a + b);
    b = next_b;
    weight *= 2.0;
    sum += weight * c * c;
  }
  K = M_PI / (a + b);
  E = K * (1.0 - sum);
}

Vec3 vortex_ring_velocity(double radius, double gamma, const Vec3& p, double core2) {
  const double rho = std::hypot(p.x(), p.y()), z = p.z();
  const double outer2 = (rho + radius) * (rho + radius) + z * z;  // squared distance to the far side
  const double inner2 = (radius - rho) * (radius - rho) + z * z;  // to the near side: the filament's distance d^2
  if (inner2 <= 1e-24 * radius * radius) return Vec3::Zero();     // on the filament, where a core's velocity vanishes
  double K, E;
  complete_elliptic_integrals(std::min(4.0 * radius * rho / outer2, 1.0 - 1e-15), K, E);
  // The filament's 1/d singularity smoothed by a core of radius c = sqrt(core2): the factor d^2 / (d^2 + c^2)
  // turns the line vortex's gamma / (2 pi d) into Scully's core, gamma d / (2 pi (d^2 + c^2)) (Scully 1975,
  // MIT ASRL TR 178-1), and leaves the field away from the filament exact (on the axis too, where the
  // radial component vanishes).
  const double a = inner2 / (inner2 + core2) * gamma / (2.0 * M_PI * std::sqrt(outer2));
  const double uz = a * (K + (radius * radius - rho * rho - z * z) / inner2 * E);
  if (rho < 1e-12 * radius) return Vec3(0, 0, uz);
  const double ur = a * z / rho * (-K + (radius * radius + rho * rho + z * z) / inner2 * E);
  return Vec3(ur * p.x() / rho, ur * p.y() / rho, uz);
}

Vec3 vortex_ring_multipole_velocity(double radius, double gamma, const Vec3& p) {
  // The ring's potential is -gamma Omega / (4 pi), Omega the solid angle of the disk it bounds, which for
  // r > R is Omega = 2 pi [(1/2) (R/r)^2 P1(cos theta) - (3/8) (R/r)^4 P3(cos theta) + (5/16) (R/r)^6 P5
  // ...] (the on-axis series of 2 pi (1 - z / sqrt(z^2 + R^2)) continued with Legendre polynomials;
  // Lamb, Hydrodynamics, art. 102): a dipole of moment gamma pi R^2 along z and its octupole
  // correction; the next term's velocity is at most (15/8) (R/r)^4 of the dipole's (on the axis).
  const double r2 = p.squaredNorm(), inv_r2 = 1.0 / r2, inv_r3 = inv_r2 / std::sqrt(r2), z = p.z(), zz = z * z * inv_r2;
  const double dipole = gamma * radius * radius / 4.0, octupole = 3.0 * gamma * std::pow(radius, 4) / 32.0;
  // grad of -(gamma R^2 / 4) z / r^3 and of (3 gamma R^4 / 32) (5 z^3 / r^7 - 3 z / r^5)
  const Vec3 u1 = dipole * inv_r3 * (3.0 * z * inv_r2 * p - Vec3::UnitZ());
  const Vec3 u3 = octupole * inv_r3 * inv_r2 * ((15.0 * zz - 3.0) * Vec3::UnitZ() + z * inv_r2 * (15.0 - 35.0 * zz) * p);
  return u1 + u3;
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
  // a ring seen from more than 7 radii: its multipole expansion, within (15/8) (R/r)^4 = 7.8e-4 of the
  // dipole's field, which skips the elliptic integrals for most of the 40 R of wake
  const double far2 = 49.0 * radius_ * radius_;
  const auto ring = [&](const Vec3& r, double sign) -> Vec3 {
    if (r.squaredNorm() < far2) return vortex_ring_velocity(radius_, sign * gamma_ds, r, core2_);
    return vortex_ring_multipole_velocity(radius_, sign * gamma_ds, r);
  };
  Vec3 u = Vec3::Zero();
  for (int k = 0; k < rings_; ++k) {
    const Vec3 c = (k + 0.5) * ds_ * d_;
    if (c.z() >= ground_) continue;  // cut at the ground
    u += ring(p - c, 1.0);
    if (ground_ < std::numeric_limits<double>::infinity()) {
      // the mirror image: a ring in the plane z = 2 g - c_z, circulating the other way
      const Vec3 image(c.x(), c.y(), 2.0 * ground_ - c.z());
      u += ring(p - image, -1.0);
    }
  }
  return u;
}

void VortexCylinderWake::set_ground(double height) {
  if (!(height > 0)) throw std::invalid_argument("vortex-cylinder wake: the ground must lie below the disk (height > 0 m)");
  ground_ = height;
}

}  // namespace ship_lrm::rotor
