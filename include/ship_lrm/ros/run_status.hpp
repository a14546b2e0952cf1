// How a run ends (launch/approach.launch): nodelets must not shut their manager down themselves
// (Debian's nodelet manager crashes in its teardown when a nodelet calls ros::requestShutdown()
// while the loaders' bonds are alive). Instead they publish on approach/status (latched,
// std_msgs/String): "done" when the approach is finished, "failed: <why>" when one cannot start;
// scripts/approach_watch.py, a required node, then exits and roslaunch ends the run cleanly.
#pragma once
#include <ros/ros.h>
#include <std_msgs/String.h>

#include <mutex>
#include <string>
#include <vector>

namespace ship_lrm::ros_layer {

constexpr const char* kRunStatusTopic = "approach/status";

inline std_msgs::String done_message() {
  std_msgs::String m;
  m.data = "done";
  return m;
}

// Publishes "failed: why" (latched; the publisher lives as long as the process). The caller logs it.
inline void report_failure(ros::NodeHandle& nh, const std::string& why) {
  static std::mutex mutex;
  static std::vector<ros::Publisher> keep;
  const std::lock_guard<std::mutex> lock(mutex);
  keep.push_back(nh.advertise<std_msgs::String>(kRunStatusTopic, 1, true));
  std_msgs::String m;
  m.data = "failed: " + why;
  keep.back().publish(m);
}

}  // namespace ship_lrm::ros_layer
