// Tail rotor: closed-form blade-element thrust with uniform momentum inflow (see tail_rotor.hpp).
#include "ship_lrm/flight/tail_rotor.hpp"

#include <cmath>

namespace ship_lrm::flight {

TailRotor::TailRotor(const TailRotorParameters& p, const Vec3& thrust_axis) : p_(p), axis_(thrust_axis.normalized()) {}

TailRotorResult TailRotor::evaluate(double pitch, double main_rotor_speed, const Vec3& air_velocity, double density,
                                    double* inflow_guess) const {
  TailRotorResult out;
  const double omega = main_rotor_speed * p_.gear_ratio;
  const double tip = omega * p_.radius;
  if (tip <= 0) return out;
  // hub velocity relative to the air = -air_velocity
  const Vec3 hub = -air_velocity;
  const double mu_z = hub.dot(axis_) / tip;  // moving along the thrust axis adds through-flow
  const double mu = (hub - hub.dot(axis_) * axis_).norm() / tip;
  const double k = 0.5 * p_.lift_slope * p_.solidity;
  const double th = pitch * (1.0 / 3.0 + 0.5 * mu * mu);
  double li = inflow_guess ? *inflow_guess : 0.05;
  // Newton on g(li) = li * 2 sqrt(mu^2 + lambda^2) - C_T(li)
  for (int it = 0; it < 30; ++it) {
    const double lam = li + mu_z;
    const double ct = k * (th - 0.5 * lam);
    const double root = std::sqrt(mu * mu + lam * lam + 1e-12);
    const double g = 2.0 * li * root - ct;
    const double dg = 2.0 * root + 2.0 * li * lam / root + 0.5 * k;
    const double step = g / dg;
    li -= step;
    if (std::abs(step) < 1e-12) break;
  }
  if (!std::isfinite(li)) li = 0;
  if (inflow_guess) *inflow_guess = li;
  const double lam = li + mu_z;
  const double ct = k * (th - 0.5 * lam);
  const double cq = lam * ct + p_.solidity * p_.profile_drag / 8.0 * (1.0 + 3.0 * mu * mu);
  const double area = M_PI * p_.radius * p_.radius;
  out.thrust = density * area * tip * tip * ct;
  out.power = density * area * tip * tip * tip * cq;
  out.inflow = li;
  out.loads.force = out.thrust * axis_;
  out.loads.moment = p_.position.cross(out.loads.force);
  return out;
}

}  // namespace ship_lrm::flight
