// The flight model's end of the rotor <-> LRM link over ROS (lrm::InflowLink): each request is
// published as ship_lrm/RotorForces on `rotor/forces`; the call waits for the ship_lrm/RotorInflow
// on `rotor/inflow` that repeats its sequence number. No answer within the timeout (wall clock)
// means the solver is gone: lrm::LinkLost, and the flight model continues on Pitt-Peters.
// The answers arrive on the link's own callback queue, which exchange() serves in the calling
// thread while it waits: a message handed straight from the publishing thread to the waiting one,
// not through the nodelet manager's dispatcher and worker threads (two thread wake-ups fewer per LBM
// step; docs/benchmarks.md at 193c1b4, "ROS layer in real time", 2026-12-02).
#pragma once
#include <ros/callback_queue.h>
#include <ros/ros.h>

#include <mutex>

#include "ship_lrm/RotorInflow.h"
#include "ship_lrm/lrm/inflow_link.hpp"

namespace ship_lrm::ros_layer {

class RosInflowLink final : public lrm::InflowLink {
 public:
  // nh: where rotor/forces and rotor/inflow are (its callback queue is not used for rotor/inflow).
  RosInflowLink(ros::NodeHandle& nh, double timeout_s);
  // Waits (wall clock) until the solver is connected both ways; false after `timeout_s`.
  bool wait_for_solver(double timeout_s);
  // Waits (wall clock) until `count` subscribers take rotor/forces (the solver and a recorder); false
  // after `timeout_s`.
  bool wait_for_request_subscribers(int count, double timeout_s);
  rotor::RotorInflow exchange(const lrm::InflowRequest& request) override;
  void set_timeout(double seconds) { timeout_s_ = seconds; }
  // Ends a wait in progress (within kCancelPoll) and every later one with LinkLost (the nodelet is
  // being unloaded). Any thread.
  void cancel();
  double last_wait_s() const { return last_wait_s_; }  // wall-clock wait of the last answered request

 private:
  void on_inflow(const ship_lrm::RotorInflow::ConstPtr& msg);  // in exchange()'s thread
  // Polls ready() every 10 ms (wall clock) until it holds (true), or cancel() or `timeout_s` (false).
  template <class Ready>
  bool wait_until(Ready ready, double timeout_s);
  static constexpr double kCancelPoll = 0.05;  // s: longest wait between checks of cancel()
  ros::CallbackQueue answers_;                 // before inflow_: outlives the subscription
  ros::Publisher forces_;
  ros::Subscriber inflow_;
  double timeout_s_;
  double last_wait_s_ = 0;
  std::mutex mutex_;
  long waiting_for_ = -1;
  bool have_answer_ = false, cancelled_ = false;
  ship_lrm::RotorInflow answer_;
};

}  // namespace ship_lrm::ros_layer
