// ship_lrm/ShipMotion: where the wake table's ship is (core: lrm::approach_ship, wake::ShipMotion).
// Translates only: on a timer in ROS time (simulated time = ROS time - clock_offset, the approach's
// clock) it publishes tf world_ned -> ship_frd (x bow, y starboard, z down; origin at the hangar-door
// base) and ship_frd -> ship (its FLU twin), ship/twist (heave and angular rates), and once, latched,
// the hull as a triangle-list marker (ship/mesh) for rviz.
#include <geometry_msgs/TwistStamped.h>
#include <nodelet/nodelet.h>
#include <tf2_ros/static_transform_broadcaster.h>
#include <tf2_ros/transform_broadcaster.h>
#include <visualization_msgs/Marker.h>

#include <pluginlib/class_list_macros.hpp>

#include "ship_lrm/lrm/approach_config.hpp"
#include "ship_lrm/ros/approach_params.hpp"
#include "ship_lrm/ros/conversions.hpp"
#include "ship_lrm/ros/run_status.hpp"
#include "ship_lrm/ros/sim_epoch.hpp"

namespace ship_lrm::ros_layer {

class ShipMotionNodelet : public nodelet::Nodelet {
 private:
  void onInit() override {
    ros::NodeHandle& nh = getNodeHandle();
    ros::NodeHandle& pnh = getPrivateNodeHandle();
    double rate = 50;
    try {
      cfg_ = approach_config(ros::NodeHandle(nh, "approach"));
      rate = param_or(pnh, "rate", 50.0);
      clock_offset_ = param_or(pnh, "clock_offset", 1.0);
      if (!(rate > 0 && rate <= 1000)) throw ParamError("parameter " + pnh.resolveName("rate") + " must lie in (0, 1000] Hz");
      if (!(clock_offset_ > 0)) throw ParamError("parameter " + pnh.resolveName("clock_offset") + " must be > 0 s");
      table_ = lrm::open_approach_table(cfg_);
      ship_ = lrm::approach_ship(cfg_, table_->info());
    } catch (const std::exception& e) {
      NODELET_FATAL("ShipMotion: %s", e.what());
      report_failure(getNodeHandle(), std::string("ShipMotion: ") + e.what());
      return;
    }
    twist_ = nh.advertise<geometry_msgs::TwistStamped>("ship/twist", 10);
    mesh_ = nh.advertise<visualization_msgs::Marker>("ship/mesh", 1, true);
    geometry_msgs::TransformStamped flu;
    flu.header.stamp = ros::Time(clock_offset_);
    flu.header.frame_id = "ship_frd";
    flu.child_frame_id = "ship";
    flu.transform = frd_to_flu();
    static_tf_.sendTransform(flu);
    epoch_.follow(nh, clock_offset_);
    // the mesh goes out once a second (and latched): a display that joins late, or that got it before
    // the first ship_frd transform and dropped it, draws it at the next one
    mesh_timer_ = nh.createWallTimer(ros::WallDuration(1.0), [this](const ros::WallTimerEvent&) { publish_mesh(); });
    timer_ = nh.createTimer(ros::Duration(1.0 / rate), &ShipMotionNodelet::tick, this);
  }

  void publish_mesh() {
    visualization_msgs::Marker m;
    m.header.frame_id = "ship_frd";
    m.ns = "ship";
    m.type = visualization_msgs::Marker::TRIANGLE_LIST;
    m.action = visualization_msgs::Marker::ADD;
    m.pose.orientation.w = 1;
    m.scale.x = m.scale.y = m.scale.z = 1;
    m.color.r = m.color.g = m.color.b = 0.55f;
    m.color.a = 1;
    for (const wake::Triangle& t : ship_.geometry->mesh())
      for (const Vec3& v : t.v) {
        geometry_msgs::Point p;
        p.x = v.x();
        p.y = v.y();
        p.z = v.z();
        m.points.push_back(p);
      }
    mesh_.publish(m);
  }

  void tick(const ros::TimerEvent&) {
    const ros::Time now = ros::Time::now();
    const double t = std::max(0.0, epoch_.to_simulated(now));
    const double table_t = std::min(table_->info().start_time + cfg_.table_offset + t, table_->info().end_time());
    const wake::ShipPlacement place = ship_.motion->placement(table_t);
    // the ship frame's origin and axes in the mean frame
    geometry_msgs::TransformStamped tf;
    tf.header.stamp = now;
    tf.header.frame_id = "world_ned";
    tf.child_frame_id = "ship_frd";
    tf.transform = transform(place.to_mean(Vec3::Zero()), Eigen::Quaterniond(place.rotation));
    tf_.sendTransform(tf);
    const wake::ShipPose pose = ship_.motion->pose(table_t);
    geometry_msgs::TwistStamped tw;
    tw.header.stamp = now;
    tw.header.frame_id = "ship_frd";
    tw.twist.linear.z = -pose.heave_rate;  // heave is up, z down
    tw.twist.angular.x = pose.roll_rate;
    tw.twist.angular.y = pose.pitch_rate;
    twist_.publish(tw);
  }

  lrm::ApproachConfig cfg_;
  double clock_offset_ = 1.0;
  SimEpoch epoch_;
  std::shared_ptr<wake::WakeTable> table_;
  lrm::ApproachShip ship_;
  ros::Publisher twist_, mesh_;
  ros::Timer timer_;
  ros::WallTimer mesh_timer_;
  tf2_ros::TransformBroadcaster tf_;
  tf2_ros::StaticTransformBroadcaster static_tf_;
};

}  // namespace ship_lrm::ros_layer

PLUGINLIB_EXPORT_CLASS(ship_lrm::ros_layer::ShipMotionNodelet, nodelet::Nodelet)
