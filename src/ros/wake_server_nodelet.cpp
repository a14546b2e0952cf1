// ship_lrm/WakeServer: loads the ship-wake table (core: wake::WakeTable via lrm::open_approach_table)
// and announces it on wake/info (latched). A missing table stops it with a message that names the
// command that makes one. (The LRM solver reads the table's windows itself, in its own process or
// the same nodelet manager; serving windows as messages is not done.)
#include <nodelet/nodelet.h>

#include <pluginlib/class_list_macros.hpp>

#include "ship_lrm/WakeInfo.h"
#include "ship_lrm/lrm/approach_config.hpp"
#include "ship_lrm/ros/approach_params.hpp"
#include "ship_lrm/ros/conversions.hpp"
#include "ship_lrm/ros/run_status.hpp"

namespace ship_lrm::ros_layer {

class WakeServerNodelet : public nodelet::Nodelet {
 private:
  void onInit() override {
    ros::NodeHandle& nh = getNodeHandle();
    try {
      const lrm::ApproachConfig cfg = approach_config(ros::NodeHandle(nh, "approach"));
      table_ = lrm::open_approach_table(cfg);
      path_ = cfg.table;
    } catch (const std::exception& e) {
      NODELET_FATAL("WakeServer: %s", e.what());
      report_failure(getNodeHandle(), std::string("WakeServer: ") + e.what());
      return;
    }
    const wake::WakeTableInfo& i = table_->info();
    info_ = nh.advertise<ship_lrm::WakeInfo>("wake/info", 1, true);
    ship_lrm::WakeInfo m;
    m.header.stamp = ros::Time::now();
    m.header.frame_id = "world_ned";
    m.path = path_;
    m.ship = i.ship;
    m.scale = i.scale;
    m.motion = i.motion;
    m.start_time = i.start_time;
    m.end_time = i.end_time();
    m.frame_interval = i.frame_interval;
    m.free_stream = to_msg(lrm::free_stream(i));
    m.origin = to_msg(Vec3(i.origin[0], i.origin[1], i.origin[2]));
    m.spacing = i.spacing;
    for (int k = 0; k < 3; ++k) m.shape[k] = i.shape[k];
    info_.publish(m);
    NODELET_INFO("WakeServer: %s: ship %s (%s scale, motion %s), %d frames over %.2f s, free stream %.2f m/s", path_.c_str(),
                 i.ship.c_str(), i.scale.c_str(), i.motion.c_str(), i.frames, i.end_time() - i.start_time, lrm::free_stream(i).norm());
  }

  std::shared_ptr<wake::WakeTable> table_;
  std::string path_;
  ros::Publisher info_;
};

}  // namespace ship_lrm::ros_layer

PLUGINLIB_EXPORT_CLASS(ship_lrm::ros_layer::WakeServerNodelet, nodelet::Nodelet)
