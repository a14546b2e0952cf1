// Core structs <-> ship_lrm messages and tf frames (see conversions.hpp).
#include "ship_lrm/ros/conversions.hpp"

#include <stdexcept>
#include <string>

namespace ship_lrm::ros_layer {

geometry_msgs::Vector3 to_msg(const Vec3& v) {
  geometry_msgs::Vector3 m;
  m.x = v.x();
  m.y = v.y();
  m.z = v.z();
  return m;
}

Vec3 from_msg(const geometry_msgs::Vector3& v) { return Vec3(v.x, v.y, v.z); }

ship_lrm::RotorForces to_msg(const lrm::InflowRequest& r) {
  ship_lrm::RotorForces m;
  m.kind = r.kind == lrm::InflowRequest::Kind::Reset ? ship_lrm::RotorForces::RESET : ship_lrm::RotorForces::ADVANCE;
  m.sequence = r.sequence;
  m.time = r.state.time;
  m.dt = r.dt;
  m.table_time = r.table_time;
  m.radius = r.state.radius;
  m.rotor_speed = r.state.rotor_speed;
  m.density = r.state.density;
  m.hub_velocity = to_msg(r.state.hub_velocity);
  m.body_rate = to_msg(r.state.body_rate);
  m.aero_force = to_msg(r.state.aero_force);
  m.aero_moment = to_msg(r.state.aero_moment);
  for (const Vec3& c : r.state.harmonics.cos) m.harmonics_cos.push_back(to_msg(c));
  for (const Vec3& s : r.state.harmonics.sin) m.harmonics_sin.push_back(to_msg(s));
  m.pose_hub = to_msg(r.pose.hub);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m.pose_rotation[3 * i + j] = r.pose.rotation(i, j);
  m.pose_hub_velocity = to_msg(r.pose.hub_velocity);
  m.pose_omega = to_msg(r.pose.omega);
  return m;
}

lrm::InflowRequest from_msg(const ship_lrm::RotorForces& m) {
  const std::size_t n = rotor::kHarmonicOrder + 1;
  if (m.harmonics_cos.size() != n || m.harmonics_sin.size() != n)
    throw std::invalid_argument("RotorForces: need " + std::to_string(n) + " cosine and sine harmonics, got " +
                                std::to_string(m.harmonics_cos.size()) + " and " + std::to_string(m.harmonics_sin.size()));
  if (m.kind != ship_lrm::RotorForces::RESET && m.kind != ship_lrm::RotorForces::ADVANCE)
    throw std::invalid_argument("RotorForces: unknown kind " + std::to_string(m.kind));
  lrm::InflowRequest r;
  r.kind = m.kind == ship_lrm::RotorForces::RESET ? lrm::InflowRequest::Kind::Reset : lrm::InflowRequest::Kind::Advance;
  r.sequence = m.sequence;
  r.state.time = m.time;
  r.dt = m.dt;
  r.table_time = m.table_time;
  r.state.radius = m.radius;
  r.state.rotor_speed = m.rotor_speed;
  r.state.density = m.density;
  r.state.hub_velocity = from_msg(m.hub_velocity);
  r.state.body_rate = from_msg(m.body_rate);
  r.state.aero_force = from_msg(m.aero_force);
  r.state.aero_moment = from_msg(m.aero_moment);
  for (std::size_t k = 0; k < n; ++k) {
    r.state.harmonics.cos[k] = from_msg(m.harmonics_cos[k]);
    r.state.harmonics.sin[k] = from_msg(m.harmonics_sin[k]);
  }
  r.pose.hub = from_msg(m.pose_hub);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r.pose.rotation(i, j) = m.pose_rotation[3 * i + j];
  r.pose.hub_velocity = from_msg(m.pose_hub_velocity);
  r.pose.omega = from_msg(m.pose_omega);
  return r;
}

ship_lrm::RotorInflow to_msg(const rotor::RotorInflow& in, long sequence, double time) {
  ship_lrm::RotorInflow m;
  m.sequence = sequence;
  m.time = time;
  m.mean = to_msg(in.mean);
  m.sine = to_msg(in.sine);
  m.cosine = to_msg(in.cosine);
  return m;
}

rotor::RotorInflow from_msg(const ship_lrm::RotorInflow& m) {
  rotor::RotorInflow in;
  in.mean = from_msg(m.mean);
  in.sine = from_msg(m.sine);
  in.cosine = from_msg(m.cosine);
  return in;
}

geometry_msgs::Transform transform(const Vec3& origin, const Eigen::Quaterniond& rotation) {
  geometry_msgs::Transform t;
  t.translation = to_msg(origin);
  const Eigen::Quaterniond q = rotation.normalized();
  t.rotation.x = q.x();
  t.rotation.y = q.y();
  t.rotation.z = q.z();
  t.rotation.w = q.w();
  return t;
}

namespace {
// the axes of NED in ENU (columns): north = y_enu, east = x_enu, down = -z_enu
Mat3 ned_axes_in_enu() {
  Mat3 r;
  r << 0, 1, 0, 1, 0, 0, 0, 0, -1;
  return r;
}
}  // namespace

Mat3 flu_axes_in_frd() { return Eigen::Vector3d(1, -1, -1).asDiagonal(); }
Vec3 frd_to_flu(const Vec3& v) { return flu_axes_in_frd() * v; }

geometry_msgs::Transform world_to_ned() { return transform(Vec3::Zero(), Eigen::Quaterniond(ned_axes_in_enu())); }
geometry_msgs::Transform frd_to_flu() { return transform(Vec3::Zero(), Eigen::Quaterniond(flu_axes_in_frd())); }
Vec3 ned_to_enu(const Vec3& v) { return ned_axes_in_enu() * v; }
Eigen::Quaterniond ned_to_enu(const Eigen::Quaterniond& q) {
  return Eigen::Quaterniond(ned_axes_in_enu() * q.toRotationMatrix() * flu_axes_in_frd());
}

}  // namespace ship_lrm::ros_layer
