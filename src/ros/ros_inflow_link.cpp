// The flight model's end of the rotor <-> LRM link over ROS (see ros_inflow_link.hpp).
#include "ship_lrm/ros/ros_inflow_link.hpp"

#include <algorithm>
#include <chrono>
#include <sstream>
#include <thread>

#include "ship_lrm/ros/conversions.hpp"

namespace ship_lrm::ros_layer {

RosInflowLink::RosInflowLink(ros::NodeHandle& nh, double timeout_s) : timeout_s_(timeout_s) {
  forces_ = nh.advertise<ship_lrm::RotorForces>("rotor/forces", 1000);  // deep: a recorder held up by the burst at t = 0 keeps it
  ros::NodeHandle own(nh);
  own.setCallbackQueue(&answers_);
  inflow_ = own.subscribe("rotor/inflow", 4, &RosInflowLink::on_inflow, this, ros::TransportHints().tcpNoDelay());
}

template <class Ready>
bool RosInflowLink::wait_until(Ready ready, double timeout_s) {
  const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  while (ros::ok() && std::chrono::steady_clock::now() < until) {
    if (ready()) return true;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (cancelled_) return false;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return false;
}

bool RosInflowLink::wait_for_solver(double timeout_s) {
  return wait_until([this] { return forces_.getNumSubscribers() > 0 && inflow_.getNumPublishers() > 0; }, timeout_s);
}

bool RosInflowLink::wait_for_request_subscribers(int count, double timeout_s) {
  return wait_until([this, count] { return static_cast<int>(forces_.getNumSubscribers()) >= count; }, timeout_s);
}

void RosInflowLink::on_inflow(const ship_lrm::RotorInflow::ConstPtr& msg) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (msg->sequence != waiting_for_) return;  // a late answer to a request given up on
  answer_ = *msg;
  have_answer_ = true;
}

void RosInflowLink::cancel() {
  std::lock_guard<std::mutex> lock(mutex_);
  cancelled_ = true;
}

rotor::RotorInflow RosInflowLink::exchange(const lrm::InflowRequest& request) {
  ship_lrm::RotorForces msg = to_msg(request);
  msg.header.stamp = ros::Time::now();
  {
    std::lock_guard<std::mutex> lock(mutex_);
    waiting_for_ = request.sequence;
    have_answer_ = false;
  }
  const auto start = std::chrono::steady_clock::now();
  const auto until = start + std::chrono::duration<double>(timeout_s_);
  forces_.publish(msg);
  bool answered = false;
  while (ros::ok()) {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (have_answer_ || cancelled_) {
        answered = have_answer_;
        break;
      }
    }
    const double left = std::chrono::duration<double>(until - std::chrono::steady_clock::now()).count();
    if (left <= 0) break;
    // returns as soon as an answer (or a stale one) is queued, else after the wait
    answers_.callAvailable(ros::WallDuration(std::min(left, kCancelPoll)));
  }
  std::lock_guard<std::mutex> lock(mutex_);
  waiting_for_ = -1;
  if (!answered) {
    std::ostringstream m;
    m << "the LRM solver did not answer request " << request.sequence << " (t = " << request.state.time << " s) within " << timeout_s_
      << " s";
    if (forces_.getNumSubscribers() == 0) m << "; nothing subscribes to " << forces_.getTopic() << " any more";
    throw lrm::LinkLost(m.str());
  }
  last_wait_s_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return from_msg(answer_);
}

}  // namespace ship_lrm::ros_layer
