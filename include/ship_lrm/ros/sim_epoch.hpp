// Where simulated time 0 lies in ROS time (the approach's nodelets): ROS time = epoch + simulated time.
// The FlightModel publishes the epoch latched on approach/epoch (std_msgs/Time) before its first step:
// the clock offset (1 s) in simulated time, where /clock runs from the epoch; the wall-clock time at
// the start in a run paced to the wall clock (realtime:=true), so that every stamp (tf, loads,
// slices) is current for rviz and tf listeners. Other nodelets stamp their messages with it.
#pragma once
#include <ros/ros.h>
#include <std_msgs/Time.h>

#include <atomic>

namespace ship_lrm::ros_layer {

constexpr const char* kEpochTopic = "approach/epoch";

class SimEpoch {
 public:
  // Follows approach/epoch in nh's namespace; until it arrives, `fallback` (the clock offset) holds.
  void follow(ros::NodeHandle& nh, double fallback) {
    seconds_ = fallback;
    sub_ = nh.subscribe<std_msgs::Time>(kEpochTopic, 1, [this](const std_msgs::Time::ConstPtr& m) { seconds_ = m->data.toSec(); });
  }
  ros::Time stamp(double t) const { return ros::Time(seconds_.load() + t); }
  double to_simulated(const ros::Time& t) const { return t.toSec() - seconds_.load(); }

 private:
  std::atomic<double> seconds_{1.0};
  ros::Subscriber sub_;
};

}  // namespace ship_lrm::ros_layer
