// ship_lrm/Scenario: the pilot's side of a run. Translates a joystick (sensor_msgs/Joy on `joy`, e.g.
// from the joy package's joy_node) into ship_lrm/PilotControls on pilot/controls for the FlightModel.
// The stick is centred on the trim (pilot/trim, latched by the FlightModel): controls = trim + gain *
// axis, per channel, with a dead band, clamped to 0-100 % of travel, so the run starts trimmed and
// a stick at rest leaves it trimmed. The message keeps the Joy's stamp (or now, when it has none),
// so the FlightModel's loads can be traced back to the input that caused them (pilot_stamp).
// Parameters (private): axis_collective, axis_longitudinal, axis_lateral, axis_pedal (Joy axis index,
// -1: not used), gain_* (% per unit deflection; the sign sets the direction), dead_band.
#include <nodelet/nodelet.h>
#include <sensor_msgs/Joy.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <mutex>
#include <pluginlib/class_list_macros.hpp>

#include "ship_lrm/PilotControls.h"
#include "ship_lrm/ros/approach_params.hpp"
#include "ship_lrm/ros/run_status.hpp"

namespace ship_lrm::ros_layer {

class ScenarioNodelet : public nodelet::Nodelet {
 private:
  struct Channel {
    const char* name;
    int axis;
    double gain;  // % per unit deflection
  };

  void onInit() override {
    ros::NodeHandle& nh = getNodeHandle();
    ros::NodeHandle& pnh = getPrivateNodeHandle();
    // defaults for a common gamepad: left stick vertical = collective (up: more), horizontal = pedal
    // (left: +1, left pedal); right stick vertical = longitudinal (up: forward), horizontal = lateral
    channels_ = {Channel{"collective", 1, 20.0}, Channel{"longitudinal", 4, 20.0}, Channel{"lateral", 3, -20.0},
                 Channel{"pedal", 0, -20.0}};
    try {
      for (Channel& c : channels_) {
        c.axis = param_or(pnh, std::string("axis_") + c.name, c.axis);
        c.gain = param_or(pnh, std::string("gain_") + c.name, c.gain);
        if (c.axis < -1) throw ParamError("parameter " + pnh.resolveName(std::string("axis_") + c.name) + " must be >= -1");
        if (!std::isfinite(c.gain)) throw ParamError("parameter " + pnh.resolveName(std::string("gain_") + c.name) + " must be finite");
      }
      dead_band_ = param_or(pnh, "dead_band", 0.05);
      if (!(dead_band_ >= 0 && dead_band_ < 1)) throw ParamError("parameter " + pnh.resolveName("dead_band") + " must lie in [0, 1)");
    } catch (const std::exception& e) {
      NODELET_FATAL("Scenario: %s", e.what());
      report_failure(nh, std::string("Scenario: ") + e.what());
      return;
    }
    controls_ = nh.advertise<ship_lrm::PilotControls>("pilot/controls", 4);
    trim_ = nh.subscribe("pilot/trim", 1, &ScenarioNodelet::on_trim, this);
    joy_ = nh.subscribe("joy", 4, &ScenarioNodelet::on_joy, this, ros::TransportHints().tcpNoDelay());
  }

  void on_trim(const ship_lrm::PilotControls::ConstPtr& m) {
    std::lock_guard<std::mutex> lock(mutex_);
    centre_ = {m->collective, m->longitudinal, m->lateral, m->pedal};
    have_trim_ = true;
  }

  void on_joy(const sensor_msgs::Joy::ConstPtr& joy) {
    std::array<double, 4> centre;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (!have_trim_) {
        NODELET_WARN_THROTTLE(5, "Scenario: no trim on pilot/trim yet; joystick input ignored");
        return;
      }
      centre = centre_;
    }
    std::array<double, 4> out{};
    for (size_t i = 0; i < channels_.size(); ++i) {
      const Channel& c = channels_[i];
      double a = 0;
      if (c.axis >= 0) {
        if (static_cast<size_t>(c.axis) >= joy->axes.size()) {
          NODELET_WARN_THROTTLE(5, "Scenario: the joystick has %zu axes; axis_%s = %d does not exist", joy->axes.size(), c.name, c.axis);
        } else if (std::isfinite(joy->axes[c.axis])) {
          a = std::clamp(static_cast<double>(joy->axes[c.axis]), -1.0, 1.0);
          a = std::abs(a) <= dead_band_ ? 0.0 : a;
        }
      }
      out[i] = std::clamp(centre[i] + c.gain * a, 0.0, 100.0);
    }
    ship_lrm::PilotControls m;
    m.header.stamp = joy->header.stamp.isZero() ? ros::Time::now() : joy->header.stamp;
    m.collective = out[0];
    m.longitudinal = out[1];
    m.lateral = out[2];
    m.pedal = out[3];
    controls_.publish(m);
  }

  std::array<Channel, 4> channels_{};
  double dead_band_ = 0.05;
  std::mutex mutex_;
  std::array<double, 4> centre_{};
  bool have_trim_ = false;
  ros::Publisher controls_;
  ros::Subscriber trim_, joy_;
};

}  // namespace ship_lrm::ros_layer

PLUGINLIB_EXPORT_CLASS(ship_lrm::ros_layer::ScenarioNodelet, nodelet::Nodelet)
