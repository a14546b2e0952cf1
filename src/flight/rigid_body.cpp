// Six-degree-of-freedom rigid body with quaternion attitude and RK4 (equations in rigid_body.hpp).
#include "ship_lrm/flight/rigid_body.hpp"

#include <Eigen/Dense>
#include <cmath>

namespace ship_lrm::flight {

Vec3 RigidBodyState::euler() const {
  const Eigen::Matrix3d r = attitude.toRotationMatrix();  // body -> NED
  const double pitch = std::asin(std::clamp(-r(2, 0), -1.0, 1.0));
  const double roll = std::atan2(r(2, 1), r(2, 2));
  const double yaw = std::atan2(r(1, 0), r(0, 0));
  return {roll, pitch, yaw};
}

Eigen::Quaterniond RigidBodyState::from_euler(double roll, double pitch, double yaw) {
  return Eigen::Quaterniond(Eigen::AngleAxisd(yaw, Vec3::UnitZ()) * Eigen::AngleAxisd(pitch, Vec3::UnitY()) *
                            Eigen::AngleAxisd(roll, Vec3::UnitX()));
}

RigidBody::RigidBody(double mass, const Eigen::Matrix3d& inertia) : mass_(mass), inertia_(inertia), inertia_inv_(inertia.inverse()) {}

RigidBodyDerivative RigidBody::derivative(const RigidBodyState& s, const Wrench& w) const {
  RigidBodyDerivative d;
  d.position_rate = s.attitude * s.velocity;
  d.acceleration = w.force / mass_ - s.rate.cross(s.velocity);
  d.angular_acceleration = inertia_inv_ * (w.moment - s.rate.cross(inertia_ * s.rate));
  const Eigen::Quaterniond omega(0, s.rate.x(), s.rate.y(), s.rate.z());
  const Eigen::Quaterniond qd = s.attitude * omega;
  d.attitude_rate = 0.5 * Eigen::Vector4d(qd.w(), qd.x(), qd.y(), qd.z());
  return d;
}

namespace {
RigidBodyState advance(const RigidBodyState& s, const RigidBodyDerivative& d, double h) {
  RigidBodyState o;
  o.position = s.position + h * d.position_rate;
  o.velocity = s.velocity + h * d.acceleration;
  o.rate = s.rate + h * d.angular_acceleration;
  o.attitude = Eigen::Quaterniond(s.attitude.w() + h * d.attitude_rate[0], s.attitude.x() + h * d.attitude_rate[1],
                                  s.attitude.y() + h * d.attitude_rate[2], s.attitude.z() + h * d.attitude_rate[3]);
  return o;
}
}  // namespace

RigidBodyState RigidBody::step(const RigidBodyState& s, double dt, const std::function<Wrench(const RigidBodyState&)>& loads) const {
  const RigidBodyDerivative k1 = derivative(s, loads(s));
  const RigidBodyState s2 = advance(s, k1, 0.5 * dt);
  const RigidBodyDerivative k2 = derivative(s2, loads(s2));
  const RigidBodyState s3 = advance(s, k2, 0.5 * dt);
  const RigidBodyDerivative k3 = derivative(s3, loads(s3));
  const RigidBodyState s4 = advance(s, k3, dt);
  const RigidBodyDerivative k4 = derivative(s4, loads(s4));
  RigidBodyDerivative sum;
  sum.position_rate = (k1.position_rate + 2 * k2.position_rate + 2 * k3.position_rate + k4.position_rate) / 6.0;
  sum.acceleration = (k1.acceleration + 2 * k2.acceleration + 2 * k3.acceleration + k4.acceleration) / 6.0;
  sum.angular_acceleration =
      (k1.angular_acceleration + 2 * k2.angular_acceleration + 2 * k3.angular_acceleration + k4.angular_acceleration) / 6.0;
  sum.attitude_rate = (k1.attitude_rate + 2 * k2.attitude_rate + 2 * k3.attitude_rate + k4.attitude_rate) / 6.0;
  RigidBodyState o = advance(s, sum, dt);
  o.attitude.normalize();
  return o;
}

Vec3 RigidBody::angular_momentum_world(const RigidBodyState& s) const { return s.attitude * (inertia_ * s.rate); }

double RigidBody::kinetic_energy(const RigidBodyState& s) const {
  return 0.5 * mass_ * s.velocity.squaredNorm() + 0.5 * s.rate.dot(inertia_ * s.rate);
}

}  // namespace ship_lrm::flight
