// Tail rotor: uniform-inflow actuator disk with the closed-form blade-element thrust of a rotor without
// flapping, solved with momentum theory each call (Padfield, Helicopter Flight Dynamics, 2nd ed.,
// 3.2.1 and 3.2.2; Bramwell, Done & Balmford, Bramwell's Helicopter Dynamics, ch. 2):
//   C_T = (a s / 2) (theta (1/3 + mu^2/2) - lambda / 2),  lambda = lambda_i + mu_z,
//   lambda_i = C_T / (2 sqrt(mu^2 + lambda^2)),  C_Q = lambda C_T + s delta / 8 (1 + 3 mu^2).
#pragma once

#include "ship_lrm/flight/parameters.hpp"
#include "ship_lrm/flight/rigid_body.hpp"

namespace ship_lrm::flight {

struct TailRotorResult {
  Wrench loads;       // body axes, about the cg
  double thrust = 0;  // N along the thrust axis
  double power = 0;   // W
  double inflow = 0;  // lambda_i
};

class TailRotor {
 public:
  // thrust_axis: unit vector in body axes along which positive thrust acts.
  TailRotor(const TailRotorParameters& p, const Vec3& thrust_axis);
  // air_velocity: velocity of the air relative to the tail rotor hub, body axes.
  TailRotorResult evaluate(double pitch, double main_rotor_speed, const Vec3& air_velocity, double density, double* inflow_guess) const;
  const Vec3& thrust_axis() const { return axis_; }

 private:
  TailRotorParameters p_;
  Vec3 axis_;
};

}  // namespace ship_lrm::flight
