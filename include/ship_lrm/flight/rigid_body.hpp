// Six-degree-of-freedom rigid body (the fuselage with everything rigidly attached): NED world,
// body FRD at the centre of gravity, attitude as a unit quaternion body -> NED, classical RK4.
//   dp/dt = R v,  dv/dt = F/m - omega x v,  dq/dt = 1/2 q (0, omega),  I domega/dt = M - omega x I omega
// (e.g. Padfield, Helicopter Flight Dynamics, 2nd ed., ch. 3.2.1; Stevens & Lewis, Aircraft Control
// and Simulation, ch. 1).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <functional>

#include "ship_lrm/common/vec.hpp"

namespace ship_lrm::flight {

struct RigidBodyState {
  Vec3 position = Vec3::Zero();                                  // m, NED
  Vec3 velocity = Vec3::Zero();                                  // m/s, body FRD
  Eigen::Quaterniond attitude = Eigen::Quaterniond::Identity();  // body -> NED
  Vec3 rate = Vec3::Zero();                                      // rad/s, body (p, q, r)

  // Euler angles (roll Phi, pitch Theta, yaw Psi), rad, aerospace 3-2-1 sequence.
  Vec3 euler() const;
  static Eigen::Quaterniond from_euler(double roll, double pitch, double yaw);
};

struct Wrench {
  Vec3 force = Vec3::Zero(), moment = Vec3::Zero();  // body axes, about the cg
  Wrench& operator+=(const Wrench& o) {
    force += o.force;
    moment += o.moment;
    return *this;
  }
};

struct RigidBodyDerivative {
  Vec3 position_rate, acceleration, angular_acceleration;
  Eigen::Vector4d attitude_rate;  // (w, x, y, z)
};

class RigidBody {
 public:
  RigidBody(double mass, const Eigen::Matrix3d& inertia);
  double mass() const { return mass_; }
  const Eigen::Matrix3d& inertia() const { return inertia_; }

  RigidBodyDerivative derivative(const RigidBodyState& s, const Wrench& w) const;
  // One RK4 step; `loads` gives the wrench for a state (called four times).
  RigidBodyState step(const RigidBodyState& s, double dt, const std::function<Wrench(const RigidBodyState&)>& loads) const;

  // Angular momentum in NED axes and kinetic energy (for conservation checks).
  Vec3 angular_momentum_world(const RigidBodyState& s) const;
  double kinetic_energy(const RigidBodyState& s) const;

 private:
  double mass_;
  Eigen::Matrix3d inertia_, inertia_inv_;
};

}  // namespace ship_lrm::flight
