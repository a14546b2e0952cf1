// Translation between the core's structs and ship_lrm's ROS messages, and the tf frames of REP 103/105
// (docs/user_guide.md, "tf tree"): the core's mean frame (x forward along the ship's course, y starboard,
// z down) is `world_ned`, a child of the ENU root `world`; FRD bodies get FLU twins by a half turn
// about x. Nothing here computes physics: values are copied, float64 to double, so a request
// that crosses ROS arrives bit for bit.
#pragma once
#include <geometry_msgs/Quaternion.h>
#include <geometry_msgs/Transform.h>
#include <geometry_msgs/TransformStamped.h>
#include <geometry_msgs/Vector3.h>

#include <Eigen/Geometry>

#include "ship_lrm/RotorForces.h"
#include "ship_lrm/RotorInflow.h"
#include "ship_lrm/common/vec.hpp"
#include "ship_lrm/lrm/inflow_link.hpp"

namespace ship_lrm::ros_layer {

geometry_msgs::Vector3 to_msg(const Vec3& v);
Vec3 from_msg(const geometry_msgs::Vector3& v);

ship_lrm::RotorForces to_msg(const lrm::InflowRequest& r);
lrm::InflowRequest from_msg(const ship_lrm::RotorForces& m);  // std::invalid_argument for a malformed message
ship_lrm::RotorInflow to_msg(const rotor::RotorInflow& in, long sequence, double time);
rotor::RotorInflow from_msg(const ship_lrm::RotorInflow& m);

// tf: a transform whose child frame has origin `origin` and axes `rotation` (child -> parent) in the parent.
geometry_msgs::Transform transform(const Vec3& origin, const Eigen::Quaterniond& rotation);
// world (ENU) -> world_ned, and an FRD frame -> its FLU twin (both fixed)
geometry_msgs::Transform world_to_ned();
geometry_msgs::Transform frd_to_flu();
// The FLU twin's axes in its FRD frame (a half turn about x), and a vector's FLU components
Mat3 flu_axes_in_frd();
Vec3 frd_to_flu(const Vec3& v);
// A vector in world_ned (NED) axes expressed in world (ENU) axes, and the same for a rotation
Vec3 ned_to_enu(const Vec3& v);
Eigen::Quaterniond ned_to_enu(const Eigen::Quaterniond& q_body_to_ned);  // body FRD -> ENU becomes body FLU -> ENU

}  // namespace ship_lrm::ros_layer
