// ship_lrm/FlightModel: the Bo 105 blade-element flight model (core: lrm::ShipApproach, the approach
// of thesis 9.1 with fixed controls along the prescribed path). Translates only: parameters ->
// ApproachConfig, the inflow link -> ROS topics (RosInflowLink), the core's samples -> messages and tf.
// Runs its loop on its own thread in simulated time (publishes /clock: ROS time = clock_offset +
// simulated time), or paced to the wall clock (realtime:=true): then each step's LRM inflow has a
// firm deadline (the step's due time; core: RealTimeInflow), and a late one is replaced by
// Pitt-Peters for that step and counted. When the LRM solver stops answering for lrm_timeout, the core
// falls back to Pitt-Peters for good and the diagnostics say so at ERROR level.
// Pilot input: ship_lrm/PilotControls on pilot/controls replace the trim's controls from the next
// step on; the loads of that step are published at once (besides the output_interval grid) and carry
// the input's stamp (pilot_stamp), so the input-to-loads latency can be measured. The trim's controls
// go out latched on pilot/trim (the Scenario nodelet centres the stick on them).
// Free flight (approach/free_flight, fly.launch): the airframe is held on the path during the start-up,
// which re-trims the controls for the inflow model (pilot input waits), then flies freely; the
// trimmed controls go out again on pilot/trim at the release. A run that ends where the skids touch
// the ship or the sea says so (WARN).
// Service `trim` (ship_lrm/Trim): the Pitt-Peters trim of this helicopter for a speed and climb angle.
#include <diagnostic_updater/diagnostic_updater.h>
#include <geometry_msgs/WrenchStamped.h>
#include <nav_msgs/Odometry.h>
#include <nodelet/nodelet.h>
#include <rosgraph_msgs/Clock.h>
#include <std_msgs/String.h>
#include <tf2_ros/static_transform_broadcaster.h>
#include <tf2_ros/transform_broadcaster.h>
#include <visualization_msgs/MarkerArray.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <mutex>
#include <optional>
#include <pluginlib/class_list_macros.hpp>
#include <thread>

#include "ship_lrm/PilotControls.h"
#include "ship_lrm/RotorLoads.h"
#include "ship_lrm/Trim.h"
#include "ship_lrm/flight/parameters.hpp"
#include "ship_lrm/flight/trim.hpp"
#include "ship_lrm/lrm/approach.hpp"
#include "ship_lrm/lrm/deadline_watch.hpp"
#include "ship_lrm/lrm/wall_clock_pacer.hpp"
#include "ship_lrm/ros/approach_params.hpp"
#include "ship_lrm/ros/conversions.hpp"
#include "ship_lrm/ros/duplicate_delivery.hpp"
#include "ship_lrm/ros/ros_inflow_link.hpp"
#include "ship_lrm/ros/run_status.hpp"
#include "ship_lrm/ros/sim_epoch.hpp"

namespace ship_lrm::ros_layer {

class FlightModelNodelet : public nodelet::Nodelet {
 public:
  ~FlightModelNodelet() override {
    stop_ = true;
    if (link_) link_->cancel();  // a wait for the solver ends now, not after lrm_timeout
    if (thread_.joinable()) thread_.join();
  }

 private:
  void onInit() override {
    ros::NodeHandle& nh = getNodeHandle();
    ros::NodeHandle& pnh = getPrivateNodeHandle();
    try {
      cfg_ = approach_config(ros::NodeHandle(nh, "approach"));
      realtime_ = param_or(pnh, "realtime", false);
      lrm_timeout_ = param_or(pnh, "lrm_timeout", 30.0);
      connect_timeout_ = param_or(pnh, "connect_timeout", 60.0);
      output_interval_ = param_or(pnh, "output_interval", 0.01);
      tf_interval_ = param_or(pnh, "tf_interval", 0.02);
      clock_offset_ = param_or(pnh, "clock_offset", 1.0);
      wait_for_subscribers_ = param_or(pnh, "wait_for_loads_subscribers", 0);
      wait_for_recorder_ = param_or(pnh, "wait_for_recorder", false);
      request_subscribers_ = param_or(pnh, "request_subscribers", 1);
      min_step_wall_ = param_or(pnh, "min_step_wall", 0.0);
      if (!(min_step_wall_ >= 0.0 && min_step_wall_ <= 1.0))
        throw ParamError("parameter " + pnh.resolveName("min_step_wall") + " must lie in [0, 1] s, got " + std::to_string(min_step_wall_));
      const std::string mode = param_or(pnh, "realtime_mode", std::string("lockstep"));
      if (mode != "lockstep" && mode != "pipelined")
        throw ParamError("parameter " + pnh.resolveName("realtime_mode") + " must be lockstep or pipelined, got '" + mode + "'");
      realtime_mode_ = mode == "pipelined" ? lrm::RealTimeMode::Pipelined : lrm::RealTimeMode::LockStep;
      const std::string config = param_or(pnh, "helicopter_config", std::string(""));
      params_ = config.empty() ? flight::load_default_bo105() : flight::load_helicopter_parameters(config);
      // param_or has refused what is not a finite number
      if (!(lrm_timeout_ > 0)) throw ParamError("parameter " + pnh.resolveName("lrm_timeout") + " must be > 0 s");
      if (!(connect_timeout_ > 0)) throw ParamError("parameter " + pnh.resolveName("connect_timeout") + " must be > 0 s");
      if (wait_for_subscribers_ < 0) throw ParamError("parameter " + pnh.resolveName("wait_for_loads_subscribers") + " must be >= 0");
      if (request_subscribers_ < 1) throw ParamError("parameter " + pnh.resolveName("request_subscribers") + " must be >= 1");
      if (!(output_interval_ > 0)) throw ParamError("parameter " + pnh.resolveName("output_interval") + " must be > 0 s");
      if (!(tf_interval_ > 0)) throw ParamError("parameter " + pnh.resolveName("tf_interval") + " must be > 0 s");
      if (!(clock_offset_ > 0)) throw ParamError("parameter " + pnh.resolveName("clock_offset") + " must be > 0 s");
    } catch (const std::exception& e) {
      NODELET_FATAL("FlightModel: %s", e.what());
      report_failure(getNodeHandle(), std::string("FlightModel: ") + e.what());
      return;
    }
    clock_ = nh.advertise<rosgraph_msgs::Clock>("/clock", 10);
    // Deep queues for what a recorder keeps: a fast simulated-time run publishes faster than a busy
    // recorder reads, and a full queue drops its oldest message (a bag once lacked its second load).
    loads_ = nh.advertise<ship_lrm::RotorLoads>("rotor/loads", 10000);
    wrench_ = nh.advertise<geometry_msgs::WrenchStamped>("rotor/wrench", 1000);
    odom_ = nh.advertise<nav_msgs::Odometry>("odom", 1000);
    markers_ = nh.advertise<visualization_msgs::MarkerArray>("helicopter/markers", 2);
    status_ = nh.advertise<std_msgs::String>(kRunStatusTopic, 1, true);
    epoch_pub_ = nh.advertise<std_msgs::Time>(kEpochTopic, 1, true);
    trim_pub_ = nh.advertise<ship_lrm::PilotControls>("pilot/trim", 1, true);
    pilot_ = nh.subscribe("pilot/controls", 4, &FlightModelNodelet::on_pilot, this, ros::TransportHints().tcpNoDelay());
    trim_service_ = nh.advertiseService("trim", &FlightModelNodelet::on_trim, this);
    if (wait_for_recorder_)  // `rosbag record --publish` says begin_write once it has opened the bag and spins
      begin_write_ = nh.subscribe("begin_write", 1, &FlightModelNodelet::on_begin_write, this);
    diagnostics_.setHardwareID("ship_lrm flight model");
    diagnostics_.add("flight model", this, &FlightModelNodelet::diagnose);
    if (cfg_.inflow == "lrm") link_ = std::make_shared<RosInflowLink>(nh, lrm_timeout_);
    thread_ = std::thread([this] { run(); });
  }

  ros::Time stamp(double t) const { return ros::Time(epoch_ + t); }

  void on_begin_write(const std_msgs::String::ConstPtr&) { recorder_ready_ = true; }

  void on_pilot(const ship_lrm::PilotControls::ConstPtr& m) {
    {  // an input delivered twice (duplicate_delivery.hpp) is one input: applied and published once
      std::lock_guard<std::mutex> lock(pilot_mutex_);
      if (last_pilot_msg_ && same_message_again(*m, *last_pilot_msg_)) return;
      last_pilot_msg_ = m;
    }
    flight::PilotControls c;
    c.collective = m->collective;
    c.longitudinal = m->longitudinal;
    c.lateral = m->lateral;
    c.pedal = m->pedal;
    for (double* v : {&c.collective, &c.longitudinal, &c.lateral, &c.pedal}) {
      if (!std::isfinite(*v)) {
        NODELET_WARN_THROTTLE(5, "FlightModel: ignoring pilot controls that are not finite");
        return;
      }
      if (*v < 0 || *v > 100) {
        NODELET_WARN_THROTTLE(5, "FlightModel: pilot controls outside 0-100 %% are clamped");
        *v = std::clamp(*v, 0.0, 100.0);
      }
    }
    std::lock_guard<std::mutex> lock(pilot_mutex_);
    pilot_controls_ = c;
    pilot_msg_stamp_ = m->header.stamp;
    pilot_new_ = true;
  }

  // A steady flight's Pitt-Peters trim (core: flight::trim); a bad request or a trim that does not
  // converge answers converged = false with the reason, never an exception into ROS.
  bool on_trim(ship_lrm::Trim::Request& req, ship_lrm::Trim::Response& res) {
    res.converged = false;
    if (!std::isfinite(req.speed) || req.speed < 0 || req.speed > 100) {
      res.message = "speed must lie in [0, 100] m/s, got " + std::to_string(req.speed);
      return true;
    }
    if (!std::isfinite(req.climb_angle) || std::abs(req.climb_angle) > 0.5 * M_PI) {
      res.message = "climb_angle must lie in [-pi/2, pi/2] rad, got " + std::to_string(req.climb_angle);
      return true;
    }
    try {
      flight::Helicopter heli(params_);  // Pitt-Peters
      flight::TrimTarget target;
      target.speed = req.speed;
      target.climb_angle = req.climb_angle;
      const flight::TrimResult t = flight::trim(heli, target);
      res.converged = t.converged;
      res.message = t.message;
      res.collective = t.controls.collective;
      res.longitudinal = t.controls.longitudinal;
      res.lateral = t.controls.lateral;
      res.pedal = t.controls.pedal;
      res.pitch = t.pitch;
      res.roll = t.roll;
      res.main_power = t.main_power;
    } catch (const std::exception& e) {
      res.message = std::string("trim failed: ") + e.what();
    }
    return true;
  }

  // the newest pilot input, if one came since the last step (applied before the next)
  bool take_pilot_input() {
    std::lock_guard<std::mutex> lock(pilot_mutex_);
    if (!pilot_new_) return false;
    if (cfg_.free_flight && !approach_->released()) {  // the start-up re-trims the controls; the stick waits
      pilot_new_ = false;
      NODELET_INFO_ONCE("FlightModel: pilot input waits for the release at t = %g s (the start-up re-trims the controls)", cfg_.startup);
      return false;
    }
    pilot_new_ = false;
    approach_->helicopter().set_controls(pilot_controls_);
    pilot_stamp_ = pilot_msg_stamp_;
    return true;
  }

  void run() {
    epoch_ = realtime_ ? ros::WallTime::now().toSec() : clock_offset_;  // refined at the start in real time
    if (!realtime_) publish_clock(0.0);
    // A recorder (rosbag) or a test that must see every load subscribes before the first step. Being
    // subscribed is not enough for rosbag record: it spins its callbacks only after its clock is valid
    // and its bag open, and until then keeps only the newest 100 messages of a topic, so a fast
    // simulated-time run lost its first load. It says begin_write (--publish) when it spins; until
    // then the clock of t = 0 goes out again, so that a recorder that connected late has a valid time.
    const auto wait_until = std::chrono::steady_clock::now() + std::chrono::duration<double>(connect_timeout_);
    const auto waiting = [this] {
      return static_cast<int>(loads_.getNumSubscribers()) < wait_for_subscribers_ || (wait_for_recorder_ && !recorder_ready_);
    };
    while (!stop_ && ros::ok() && waiting() && std::chrono::steady_clock::now() < wait_until) {
      if (!realtime_) publish_clock(0.0);
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    if (static_cast<int>(loads_.getNumSubscribers()) < wait_for_subscribers_)
      NODELET_WARN("FlightModel: only %u of %d subscribers on rotor/loads after %g s; starting", loads_.getNumSubscribers(),
                   wait_for_subscribers_, connect_timeout_);
    if (wait_for_recorder_ && !recorder_ready_)
      NODELET_WARN(
          "FlightModel: no begin_write from the recorder (rosbag record --publish) after %g s; starting, the bag may miss "
          "the first loads",
          connect_timeout_);
    begin_write_.shutdown();
    if (link_ && !link_->wait_for_solver(connect_timeout_)) {
      NODELET_ERROR("FlightModel: no LRM solver on %s within %g s; flying on Pitt-Peters",
                    getNodeHandle().resolveName("rotor/forces").c_str(), connect_timeout_);
      link_->set_timeout(1e-3);
    } else if (link_ && request_subscribers_ > 1 && !link_->wait_for_request_subscribers(request_subscribers_, connect_timeout_)) {
      NODELET_WARN("FlightModel: fewer than %d subscribers on %s after %g s (a recorder?); starting, a bag may miss the first requests",
                   request_subscribers_, getNodeHandle().resolveName("rotor/forces").c_str(), connect_timeout_);
    }
    try {
      std::optional<lrm::RealTimeMode> rt;
      if (realtime_) rt = realtime_mode_;
      approach_ = std::make_unique<lrm::ShipApproach>(cfg_, params_, link_, rt);
    } catch (const std::exception& e) {
      NODELET_FATAL("FlightModel: %s", e.what());
      report_failure(getNodeHandle(), std::string("FlightModel: ") + e.what());
      return;
    }
    NODELET_INFO("FlightModel: approach on %s, inflow %s, %g s; trim %.2f %% collective", cfg_.table.c_str(), cfg_.inflow.c_str(),
                 cfg_.duration, approach_->trim().controls.collective);
    pp_collective_ = approach_->trim().controls.collective;
    publish_trim();
    lrm::WallClockPacer pacer;  // real time: simulated time 0 is due now
    if (realtime_) epoch_ = ros::WallTime::now().toSec();
    std_msgs::Time epoch;
    epoch.data = ros::Time(epoch_);
    epoch_pub_.publish(epoch);
    send_static_tf();
    publish(true, false);
    while (!stop_ && ros::ok() && !approach_->done()) {
      const bool piloted = take_pilot_input();
      if (realtime_) approach_->set_deadline(pacer.due(approach_->time() + approach_->time_step()));
      const auto t0 = std::chrono::steady_clock::now();
      approach_->step();
      step_wall_s_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      const double t = approach_->time();
      if (!realtime_) publish_clock(t);
      ++steps_;
      if (cfg_.free_flight && !released_ && approach_->released()) {
        released_ = true;  // the stick's centre is the trim the start-up has found
        publish_trim();
        const flight::PilotControls& c = approach_->trim().controls;
        NODELET_INFO(
            "FlightModel: released at t = %.3f s, re-trimmed controls %.2f / %.2f / %.2f / %.2f %% (collective of the Pitt-Peters "
            "trim %.2f %%)",
            t, c.collective, c.longitudinal, c.lateral, c.pedal, pp_collective_);
      }
      publish(false, piloted);
      report_fallback();
      if (const lrm::RealTimeInflow* rt = approach_->realtime_inflow()) {
        const std::string late = deadline_watch_.update(approach_->time(), rt->stats());
        if (!late.empty()) NODELET_WARN("FlightModel: %s", late.c_str());
      }
      if (realtime_) {
        pacer.wait_until(t);
        overruns_ = pacer.overruns();
      } else if (min_step_wall_ > 0.0) {
        // Simulated time, recorded: no faster than min_step_wall per step, so that the recorder, which
        // keeps only its newest 100 messages per topic while it is held up, stays within them
        std::this_thread::sleep_until(t0 + std::chrono::duration<double>(min_step_wall_));
      }
    }
    if (approach_ && !approach_->end_reason().empty()) NODELET_WARN("FlightModel: free flight %s", approach_->end_reason().c_str());
    if (approach_ && approach_->done()) {
      NODELET_INFO("FlightModel: approach finished at t = %.3f s (%ld steps, t_clock/t_sim %.2f)", approach_->time(), steps_,
                   approach_->wall_seconds() / std::max(approach_->time(), 1e-9));
      diagnostics_.force_update();
      status_.publish(done_message());  // approach_watch.py ends the launch (run_status.hpp)
    }
  }

  void publish_clock(double t) {
    rosgraph_msgs::Clock c;
    c.clock = stamp(t);
    clock_.publish(c);
  }

  void report_fallback() {
    const lrm::LinkedInflow* l = approach_->linked_inflow();
    if (l && l->lost() && !reported_lost_) {
      reported_lost_ = true;
      NODELET_ERROR("FlightModel: LRM lost at t = %.3f s, continuing on Pitt-Peters: %s", approach_->time(), l->lost_reason().c_str());
      diagnostics_.force_update();
    }
  }

  void send_static_tf() {
    std::vector<geometry_msgs::TransformStamped> fixed(3);
    fixed[0].header.frame_id = "world";
    fixed[0].child_frame_id = "world_ned";
    fixed[0].transform = world_to_ned();
    fixed[1].header.frame_id = "base_link_frd";
    fixed[1].child_frame_id = "base_link";
    fixed[1].transform = frd_to_flu();
    // main_rotor: the thesis' mr frame at the hub, as its FLU twin (x forward, y port, z up the shaft)
    const auto& heli = approach_->helicopter();
    const Eigen::Matrix3d mr_flu = heli.mr_to_body() * flu_axes_in_frd();
    fixed[2].header.frame_id = "base_link_frd";
    fixed[2].child_frame_id = "main_rotor";
    fixed[2].transform = transform(heli.parameters().main_rotor.hub_position, Eigen::Quaterniond(mr_flu));
    for (auto& f : fixed) f.header.stamp = stamp(0);
    static_tf_.sendTransform(fixed);
  }

  void publish_trim() {
    const flight::PilotControls& c = approach_->trim().controls;
    ship_lrm::PilotControls m;
    m.header.stamp = stamp(approach_->time());
    m.collective = c.collective;
    m.longitudinal = c.longitudinal;
    m.lateral = c.lateral;
    m.pedal = c.pedal;
    trim_pub_.publish(m);
  }

  // true when this step's inflow is Pitt-Peters' though the LRM was asked for
  bool fell_back() const {
    const lrm::LinkedInflow* l = approach_->linked_inflow();
    if (l && l->lost()) return true;
    const lrm::RealTimeInflow* rt = approach_->realtime_inflow();
    return rt && rt->stats().last_was_fallback;
  }

  // first: the state at t = 0; piloted: this step applied new pilot input (published at once)
  void publish(bool first, bool piloted) {
    const lrm::ApproachSample& s = approach_->sample();
    const ros::Time now = stamp(s.time);
    const double eps = 0.5 * approach_->time_step();
    const bool on_grid = first || s.time >= next_output_ - eps;
    if (on_grid || piloted) {
      if (on_grid) next_output_ = first ? output_interval_ : next_output_ + output_interval_;  // the grid of `ship_lrm approach`
      ship_lrm::RotorLoads m;
      m.header.stamp = now;
      m.header.frame_id = "main_rotor";
      m.time = s.time;
      m.thrust = s.thrust;
      m.ct = s.ct;
      m.cmx = s.cmx;
      m.cmy = s.cmy;
      m.main_power = s.main_power;
      m.distance = s.distance;
      m.height_above_deck = s.height_above_deck;
      m.speed = s.speed;
      m.inflow_mean = to_msg(s.inflow_mean);
      m.fallback = fell_back();
      m.inflow_model = (cfg_.inflow == "lrm" && !m.fallback) ? "lrm" : "pitt_peters";
      m.pilot_stamp = pilot_stamp_;
      loads_.publish(m);
      // the rotor's aerodynamic load in main_rotor (FLU twin of mr: y and z change sign)
      const auto& o = approach_->helicopter().outputs();
      geometry_msgs::WrenchStamped w;
      w.header = m.header;
      w.wrench.force = to_msg(frd_to_flu(o.rotor.aero_force));
      w.wrench.torque = to_msg(frd_to_flu(o.rotor.aero_moment));
      wrench_.publish(w);
    }
    if (first || s.time >= next_tf_ - eps) {
      next_tf_ = first ? tf_interval_ : next_tf_ + tf_interval_;
      const flight::RigidBodyState& b = approach_->helicopter().body();
      geometry_msgs::TransformStamped t;
      t.header.stamp = now;
      t.header.frame_id = "world_ned";
      t.child_frame_id = "base_link_frd";
      t.transform = transform(b.position, b.attitude);
      tf_.sendTransform(t);
      nav_msgs::Odometry od;
      od.header.stamp = now;
      od.header.frame_id = "world";
      od.child_frame_id = "base_link";
      const Eigen::Vector3d p = ned_to_enu(b.position);
      od.pose.pose.position.x = p.x();
      od.pose.pose.position.y = p.y();
      od.pose.pose.position.z = p.z();
      const Eigen::Quaterniond q = ned_to_enu(b.attitude);
      od.pose.pose.orientation.x = q.x();
      od.pose.pose.orientation.y = q.y();
      od.pose.pose.orientation.z = q.z();
      od.pose.pose.orientation.w = q.w();
      od.twist.twist.linear = to_msg(frd_to_flu(b.velocity));
      od.twist.twist.angular = to_msg(frd_to_flu(b.rate));
      odom_.publish(od);
      publish_markers(now);
      diagnostics_.update();
    }
  }

  // For rviz (rviz/lrm.rviz): the fuselage (an ellipsoid of the Bo 105's size), the rotor disk, and
  // arrows of the mean inflow (0.5 m per m/s) and of the rotor's aerodynamic force (1 m per 5 kN) at the hub.
  void publish_markers(const ros::Time& now) {
    const auto& heli = approach_->helicopter();
    const double R = heli.parameters().main_rotor.radius;
    visualization_msgs::MarkerArray a;
    auto marker = [&](const char* frame, int id, int type, float r, float g, float b, float alpha) {
      visualization_msgs::Marker m;
      m.header.stamp = now;
      m.header.frame_id = frame;
      m.ns = "helicopter";
      m.id = id;
      m.type = type;
      m.action = visualization_msgs::Marker::ADD;
      m.pose.orientation.w = 1;
      m.color.r = r;
      m.color.g = g;
      m.color.b = b;
      m.color.a = alpha;
      return m;
    };
    visualization_msgs::Marker body = marker("base_link", 0, visualization_msgs::Marker::SPHERE, 0.2f, 0.35f, 0.6f, 1.0f);
    body.scale.x = 4.3;  // cabin length, width, height (Bo 105, about)
    body.scale.y = 1.6;
    body.scale.z = 1.8;
    a.markers.push_back(body);
    visualization_msgs::Marker disk = marker("main_rotor", 1, visualization_msgs::Marker::CYLINDER, 0.8f, 0.8f, 0.8f, 0.35f);
    disk.scale.x = disk.scale.y = 2 * R;
    disk.scale.z = 0.05;
    a.markers.push_back(disk);
    const auto arrow = [&](int id, const Vec3& v_flu, double scale, float r, float g, float b) {
      visualization_msgs::Marker m = marker("main_rotor", id, visualization_msgs::Marker::ARROW, r, g, b, 1.0f);
      m.scale.x = 0.25;  // shaft diameter, head diameter, head length
      m.scale.y = 0.5;
      m.scale.z = 0.6;
      geometry_msgs::Point p0, p1;
      p1.x = scale * v_flu.x();
      p1.y = scale * v_flu.y();
      p1.z = scale * v_flu.z();
      m.points = {p0, p1};
      return m;
    };
    const lrm::ApproachSample& s = approach_->sample();
    a.markers.push_back(arrow(2, frd_to_flu(s.inflow_mean), 0.5, 0.1f, 0.6f, 1.0f));
    a.markers.push_back(arrow(3, frd_to_flu(heli.outputs().rotor.aero_force), 1.0 / 5000.0, 1.0f, 0.4f, 0.1f));
    markers_.publish(a);
  }

  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& stat) {
    if (!approach_) {
      stat.summary(diagnostic_msgs::DiagnosticStatus::WARN, "starting");
      return;
    }
    const lrm::LinkedInflow* l = approach_->linked_inflow();
    const lrm::RealTimeInflow* rt = approach_->realtime_inflow();
    const double t = approach_->time();
    const double ratio = t > 0 ? approach_->wall_seconds() / t : 0.0;
    if (l && l->lost())
      stat.summary(diagnostic_msgs::DiagnosticStatus::ERROR, "LRM lost, Pitt-Peters fallback: " + l->lost_reason());
    else if (!std::isfinite(approach_->sample().thrust))
      stat.summary(diagnostic_msgs::DiagnosticStatus::ERROR, "rotor loads not finite");
    else if (rt && rt->stats().miss_fraction() > 0.01)
      stat.summary(diagnostic_msgs::DiagnosticStatus::WARN, "more than 1 % of the steps missed their LRM deadline");
    else
      stat.summary(diagnostic_msgs::DiagnosticStatus::OK, cfg_.inflow + " inflow");
    stat.add("simulated time (s)", t);
    stat.add("steps", steps_);
    stat.add("step time (ms)", 1e3 * step_wall_s_);
    stat.add("real-time ratio t_clock/t_sim", ratio);
    if (rt) {
      const lrm::RealTimeStats st = rt->stats();
      stat.add("deadline misses", st.deadline_misses);
      stat.add("deadline miss fraction", st.miss_fraction());
      stat.add("worst inflow wait (ms)", 1e3 * st.worst_wait_s);
      stat.add("real-time mode", rt->mode() == lrm::RealTimeMode::Pipelined ? "pipelined" : "lockstep");
      if (rt->mode() == lrm::RealTimeMode::Pipelined) stat.add("LBM intervals the LRM runs behind", lrm::kPipelineDepth);
    }
    if (realtime_) stat.add("steps ended after their due time", overruns_.load());
    stat.add("inflow model", l && l->lost() ? "pitt_peters (fallback)" : cfg_.inflow);
    if (l) stat.add("fallback steps", l->fallback_calls());
    stat.add("C_T", approach_->sample().ct);
  }

  lrm::ApproachConfig cfg_;
  flight::HelicopterParameters params_;
  bool realtime_ = false, reported_lost_ = false, released_ = false;
  lrm::DeadlineWatch deadline_watch_;  // says aloud when most steps of 5 s flew on Pitt-Peters
  double pp_collective_ = 0;
  lrm::RealTimeMode realtime_mode_ = lrm::RealTimeMode::LockStep;
  double epoch_ = 1.0;  // ROS time of simulated time 0 (sim_epoch.hpp)
  std::atomic<long> overruns_{0};
  std::mutex pilot_mutex_;
  flight::PilotControls pilot_controls_;
  ros::Time pilot_msg_stamp_, pilot_stamp_;
  ship_lrm::PilotControls::ConstPtr last_pilot_msg_;  // the last input taken (a copy delivered twice is not a second)
  int request_subscribers_ = 1;                       // rotor/forces: the solver, and a recorder (record_requests)
  bool pilot_new_ = false;
  double lrm_timeout_ = 30, connect_timeout_ = 60, output_interval_ = 0.01, tf_interval_ = 0.02, clock_offset_ = 1.0;
  double next_output_ = 0, next_tf_ = 0, step_wall_s_ = 0;
  double min_step_wall_ = 0;  // s of wall clock at least per step in simulated time (a recorder keeping up)
  long steps_ = 0;
  int wait_for_subscribers_ = 0;
  bool wait_for_recorder_ = false;
  std::atomic<bool> recorder_ready_{false};
  ros::Subscriber begin_write_;
  std::shared_ptr<RosInflowLink> link_;
  std::unique_ptr<lrm::ShipApproach> approach_;
  ros::Publisher clock_, loads_, wrench_, odom_, status_, epoch_pub_, trim_pub_, markers_;
  ros::Subscriber pilot_;
  ros::ServiceServer trim_service_;
  tf2_ros::TransformBroadcaster tf_;
  tf2_ros::StaticTransformBroadcaster static_tf_;
  diagnostic_updater::Updater diagnostics_;
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

}  // namespace ship_lrm::ros_layer

PLUGINLIB_EXPORT_CLASS(ship_lrm::ros_layer::FlightModelNodelet, nodelet::Nodelet)
