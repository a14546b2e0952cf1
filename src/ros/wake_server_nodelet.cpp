// ship_lrm/WakeServer: loads the ship-wake table (core: wake::WakeTable via lrm::open_approach_table),
// announces it on wake/info (latched) and serves boxes of its frames on the service wake/window
// (ship_lrm/WakeWindow) to LRM solvers that have no copy of the file (LrmSolver wake_source:=server,
// e.g. on a GPU machine). A missing table stops it with a message that names the command that makes
// one. A solver with the file (wake_source:=file, the default) reads it itself.
#include <nodelet/nodelet.h>

#include <pluginlib/class_list_macros.hpp>

#include "ship_lrm/WakeInfo.h"
#include "ship_lrm/WakeWindow.h"
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
    m.frames = i.frames;
    m.free_density = i.free_density;
    m.free_stream = to_msg(lrm::free_stream(i));
    m.origin = to_msg(Vec3(i.origin[0], i.origin[1], i.origin[2]));
    m.spacing = i.spacing;
    for (int k = 0; k < 3; ++k) m.shape[k] = i.shape[k];
    window_ = nh.advertiseService("wake/window", &WakeServerNodelet::on_window, this);  // before the announcement
    info_.publish(m);
    NODELET_INFO("WakeServer: %s: ship %s (%s scale, motion %s), %d frames over %.2f s, free stream %.2f m/s", path_.c_str(),
                 i.ship.c_str(), i.scale.c_str(), i.motion.c_str(), i.frames, i.end_time() - i.start_time, lrm::free_stream(i).norm());
  }

  // A box of one frame; a bad request is answered with ok = false and the reason.
  bool on_window(ship_lrm::WakeWindow::Request& req, ship_lrm::WakeWindow::Response& res) {
    try {
      table_->read_box(req.frame, {req.lo[0], req.lo[1], req.lo[2]}, {req.n[0], req.n[1], req.n[2]}, res.velocity, res.density);
      res.ok = true;
    } catch (const std::exception& e) {
      res.ok = false;
      res.message = e.what();
      res.velocity.clear();
      res.density.clear();
    }
    return true;
  }

  std::shared_ptr<wake::WakeTable> table_;
  std::string path_;
  ros::Publisher info_;
  ros::ServiceServer window_;
};

}  // namespace ship_lrm::ros_layer

PLUGINLIB_EXPORT_CLASS(ship_lrm::ros_layer::WakeServerNodelet, nodelet::Nodelet)
