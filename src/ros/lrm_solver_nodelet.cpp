// ship_lrm/LrmSolver: the LRM domain of the approach (core: lrm::ApproachFluid) on the CPU or a GPU
// (backend cpu|cuda|auto). Translates only: each ship_lrm/RotorForces on rotor/forces is served by the
// core (walls and faces placed for its time and pose, then the LBM advanced with its loads) and
// answered on rotor/inflow; the domain's pose goes out as tf world_ned -> lrm_domain (the mr frame at
// the hub, x forward, y starboard, z down), a plane through the hub as lrm/slice (PointCloud2 with
// x, y, z, speed, u, v, w, wall), the domain's box as lrm/domain (Marker), and diagnostics.
// wake_source: file (read the table here) or server (the WakeServer's table announced on wake/info,
// its windows through the service wake/window: for a solver on a machine without the file).
// The domain is built and every request served on the nodelet's own thread, from its own callback
// queue: one thread (and one OpenMP team) for the LBM, and a request handed straight from the
// publishing thread to it, not through the nodelet manager's dispatcher and worker threads
// (docs/benchmarks.md at 193c1b4, "ROS layer in real time", 2026-12-02).
#include <diagnostic_updater/diagnostic_updater.h>
#include <nodelet/nodelet.h>
#include <pthread.h>
#include <ros/callback_queue.h>
#include <sensor_msgs/PointCloud2.h>
#include <sensor_msgs/point_cloud2_iterator.h>
#include <tf2_ros/transform_broadcaster.h>
#include <visualization_msgs/Marker.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <deque>
#include <pluginlib/class_list_macros.hpp>
#include <thread>

#include "ship_lrm/flight/parameters.hpp"
#include "ship_lrm/lrm/approach_fluid.hpp"
#include "ship_lrm/lrm/domain_slice.hpp"
#include "ship_lrm/lrm/realtime_inflow.hpp"
#include "ship_lrm/ros/approach_params.hpp"
#include "ship_lrm/ros/conversions.hpp"
#include "ship_lrm/ros/duplicate_delivery.hpp"
#include "ship_lrm/ros/run_status.hpp"
#include "ship_lrm/ros/served_wake_table.hpp"
#include "ship_lrm/ros/sim_epoch.hpp"

namespace ship_lrm::ros_layer {

class LrmSolverNodelet : public nodelet::Nodelet {
 public:
  ~LrmSolverNodelet() override {
    stop_ = true;
    if (thread_.joinable()) thread_.join();
  }

 private:
  void onInit() override {
    ros::NodeHandle& nh = getNodeHandle();
    ros::NodeHandle& pnh = getPrivateNodeHandle();
    try {
      wake_source_ = param_or(pnh, "wake_source", std::string("file"));
      if (wake_source_ != "file" && wake_source_ != "server")
        throw ParamError("parameter " + pnh.resolveName("wake_source") + " must be file or server, got '" + wake_source_ + "'");
      cfg_ = approach_config(ros::NodeHandle(nh, "approach"), wake_source_ == "file");
      slice_interval_ = param_or(pnh, "slice_interval", 0.1);
      slice_normal_ = param_or(pnh, "slice_normal", 1);
      clock_offset_ = param_or(pnh, "clock_offset", 1.0);
      if (slice_normal_ < 0 || slice_normal_ > 2)
        throw ParamError("parameter " + pnh.resolveName("slice_normal") + " must be 0 (x), 1 (y) or 2 (z)");
      if (!(slice_interval_ > 0)) throw ParamError("parameter " + pnh.resolveName("slice_interval") + " must be > 0 s");
      if (!(clock_offset_ > 0)) throw ParamError("parameter " + pnh.resolveName("clock_offset") + " must be > 0 s");
      const std::string config = param_or(pnh, "helicopter_config", std::string(""));
      params_ = config.empty() ? flight::load_default_bo105() : flight::load_helicopter_parameters(config);
      if (cfg_.inflow != "lrm")
        NODELET_WARN("LrmSolver: approach/inflow is %s; the flight model will not ask for the LRM", cfg_.inflow.c_str());
      realtime_ = param_or(pnh, "realtime", false);
      answer_subscribers_ = param_or(pnh, "answer_subscribers", 1);
      if (answer_subscribers_ < 1) throw ParamError("parameter " + pnh.resolveName("answer_subscribers") + " must be >= 1");
      if (wake_source_ == "file") start(nullptr);
    } catch (const std::exception& e) {
      fail(e.what());
      return;
    }
    if (wake_source_ == "server") {
      NODELET_INFO("LrmSolver: waiting for the wake server's table on %s", nh.resolveName("wake/info").c_str());
      info_ = nh.subscribe("wake/info", 1, &LrmSolverNodelet::on_info, this);
    }
  }

  void fail(const std::string& why) {
    failed_ = true;
    NODELET_FATAL("LrmSolver: %s", why.c_str());
    report_failure(getNodeHandle(), "LrmSolver: " + why);
  }

  // wake_source:=server: the table the wake server announced, its windows through its service
  void on_info(const ship_lrm::WakeInfo::ConstPtr& m) {
    if (thread_.joinable() || failed_) return;
    try {
      auto table = served_wake_table(*m, getNodeHandle());
      cfg_.table = m->path;
      lrm::check_approach_table(cfg_, *table);
      start(std::move(table));
    } catch (const std::exception& e) {
      fail(e.what());
    }
  }

  // The solver's thread: the domain (on the table given, or the file's), then the topics, then the
  // requests until the nodelet is unloaded.
  void start(std::shared_ptr<wake::WakeTable> table) {
    thread_ = std::thread([this, table = std::move(table)]() mutable {
      pthread_setname_np(pthread_self(), "lrm_solver");
      try {
        build(std::move(table));
      } catch (const std::exception& e) {
        fail(e.what());
        return;
      }
      while (!stop_ && ros::ok()) jobs_.callAvailable(ros::WallDuration(0.05));
    });
  }

  void build(std::shared_ptr<wake::WakeTable> table) {
    ros::NodeHandle& nh = getNodeHandle();
    fluid_ = std::make_unique<lrm::ApproachFluid>(cfg_, params_, std::move(table));
    if (realtime_) fluid_->set_catch_up_limit(lrm::kRealTimeCatchUpSteps);
    const lrm::LrmDomain& d = fluid_->domain();
    NODELET_INFO("LrmSolver: N = %d, a = %g, %d^3 cells, %s, LBM step %.3f ms, wake table from %s", d.config().nodes, d.config().reach,
                 d.cells_per_edge(), fluid_->domain().solver().backend_name(), 1e3 * d.time_step(),
                 wake_source_ == "file" ? "the file" : "the wake server");
    // a deep queue, so that a recorder held up by the burst of answers at t = 0 keeps them all (the 16 answers
    // a bag once missed were lost before the recorder connected: wait_for_answer_subscribers)
    inflow_ = nh.advertise<ship_lrm::RotorInflow>("rotor/inflow", 1000);
    slice_ = nh.advertise<sensor_msgs::PointCloud2>("lrm/slice", 2);
    box_ = nh.advertise<visualization_msgs::Marker>("lrm/domain", 2, true);
    diagnostics_.setHardwareID("ship_lrm LRM solver");
    diagnostics_.add("LRM solver", this, &LrmSolverNodelet::diagnose);
    epoch_.follow(nh, clock_offset_);
    ros::NodeHandle jobs(nh);
    jobs.setCallbackQueue(&jobs_);
    forces_ = jobs.subscribe("rotor/forces", 4, &LrmSolverNodelet::on_forces, this, ros::TransportHints().tcpNoDelay());
  }

  ros::Time stamp(double t) const { return epoch_.stamp(t); }

  void on_forces(const ship_lrm::RotorForces::ConstPtr& msg) {
    // A request delivered twice (duplicate_delivery.hpp) is answered again, not served again: served
    // twice, it advanced the fluid twice as far.
    if (last_request_ && same_message_again(*msg, *last_request_)) {
      ++duplicates_;
      NODELET_WARN_ONCE(
          "LrmSolver: a request on %s came twice (sequence %ld); answered again, not served again (counted in the diagnostics)",
          forces_.getTopic().c_str(), static_cast<long>(msg->sequence));
      inflow_.publish(last_answer_);
      return;
    }
    if (served_ == 0) wait_for_answer_subscribers();
    // real time: ROS time is the wall clock, and the link stamps each request as it sends it
    if (realtime_) remember(delay_ms_, 1e3 * (ros::Time::now() - msg->header.stamp).toSec());
    lrm::InflowRequest r;
    try {
      r = from_msg(*msg);
    } catch (const std::exception& e) {
      NODELET_ERROR_THROTTLE(5, "LrmSolver: ignoring a malformed request: %s", e.what());
      return;
    }
    if (diverged_) return;  // the flight model falls back after its timeout
    const long steps0 = fluid_->domain().solver().steps_done();
    const auto t0 = std::chrono::steady_clock::now();
    rotor::RotorInflow in;
    try {
      in = fluid_->serve(r);
    } catch (const std::exception& e) {
      diverged_ = true;
      failure_ = e.what();
      NODELET_ERROR("LrmSolver: stopped at t = %.3f s: %s", r.state.time, e.what());
      diagnostics_.force_update();
      return;
    }
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const long steps = fluid_->domain().solver().steps_done() - steps0;
    remember(job_ms_, 1e3 * wall);
    if (steps > 0) {
      step_ms_ = 1e3 * wall / steps;
      const double cells = std::pow(fluid_->domain().cells_per_edge(), 3);
      mlups_ = cells * steps / wall * 1e-6;
    }
    ++served_;
    ship_lrm::RotorInflow answer = to_msg(in, r.sequence, r.state.time);
    answer.header.stamp = stamp(r.state.time);
    answer.header.frame_id = "lrm_domain";
    inflow_.publish(answer);
    last_request_ = msg;
    last_answer_ = answer;
    publish_views(r);
    // the updater's period is 1 s of ROS time, which a short simulated run may not see twice: the
    // first request and every 100th publish at once
    if (served_ % 100 == 1)
      diagnostics_.force_update();
    else
      diagnostics_.update();
  }

  // Before the first answer: until answer_subscribers take rotor/inflow (the flight model and a
  // recorder), at most kAnswerWait s. A recorder connects to this publisher on its own time, and a bag
  // missed the burst of answers at t = 0 (16 of 566) when the first request came before it.
  void wait_for_answer_subscribers() {
    const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(kAnswerWait);
    while (static_cast<int>(inflow_.getNumSubscribers()) < answer_subscribers_ && !stop_ && ros::ok()) {
      if (std::chrono::steady_clock::now() >= until) {
        NODELET_WARN("LrmSolver: only %u of %d subscribers on %s after %g s (a recorder?); answering, a bag may miss answers",
                     inflow_.getNumSubscribers(), answer_subscribers_, inflow_.getTopic().c_str(), kAnswerWait);
        return;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
  }
  static constexpr double kAnswerWait = 10.0;  // s (wall clock); less than the flight model's lrm_timeout (30 s)

  void publish_views(const lrm::InflowRequest& r) {
    const ros::Time now = stamp(r.state.time);
    geometry_msgs::TransformStamped t;
    t.header.stamp = now;
    t.header.frame_id = "world_ned";
    t.child_frame_id = "lrm_domain";
    t.transform = transform(r.pose.hub, Eigen::Quaterniond(r.pose.rotation));
    tf_.sendTransform(t);
    if (r.kind == lrm::InflowRequest::Kind::Advance && r.state.time + 1e-9 < next_slice_) return;
    {  // the box with every slice: a display that joins late, or dropped it before the first tf, draws it
      lrm::LrmDomain& d = fluid_->domain();
      visualization_msgs::Marker m;
      m.header.stamp = ros::Time(0);  // latched: drawn at the newest tf of the domain, wherever it is
      m.header.frame_id = "lrm_domain";
      m.ns = "lrm";
      m.type = visualization_msgs::Marker::CUBE;
      m.action = visualization_msgs::Marker::ADD;
      const int n = d.cells_per_edge() - 1;
      const Vec3 lo = d.position(0, 0, 0), hi = d.position(n, n, n);
      m.pose.position.x = 0.5 * (lo.x() + hi.x());
      m.pose.position.y = 0.5 * (lo.y() + hi.y());
      m.pose.position.z = 0.5 * (lo.z() + hi.z());
      m.pose.orientation.w = 1;
      m.scale.x = hi.x() - lo.x();
      m.scale.y = hi.y() - lo.y();
      m.scale.z = hi.z() - lo.z();
      m.color.r = 0.2f;
      m.color.g = 0.6f;
      m.color.b = 1.0f;
      m.color.a = 0.15f;
      box_.publish(m);
    }
    next_slice_ = r.state.time + slice_interval_;
    lrm::DomainSlice s = lrm::domain_slice(fluid_->domain(), slice_normal_);
    max_mach_ = s.max_mach;
    if (slice_.getNumSubscribers() == 0) return;
    lrm::add_undisturbed_air(fluid_->domain(), s);  // the air the faces take there (the wake table's)
    sensor_msgs::PointCloud2 cloud;
    cloud.header.stamp = now;
    cloud.header.frame_id = "lrm_domain";
    sensor_msgs::PointCloud2Modifier mod(cloud);
    // speed, u, v, w: the LRM's air relative to the domain; table_u, table_v, table_w: the undisturbed
    // air the faces take at the same point (the wake table's, or the free stream); difference: |LRM -
    // table| (thesis fig. 9.3 (c)), m/s, lrm_domain axes
    mod.setPointCloud2Fields(12, "x", 1, sensor_msgs::PointField::FLOAT32, "y", 1, sensor_msgs::PointField::FLOAT32, "z", 1,
                             sensor_msgs::PointField::FLOAT32, "speed", 1, sensor_msgs::PointField::FLOAT32, "u", 1,
                             sensor_msgs::PointField::FLOAT32, "v", 1, sensor_msgs::PointField::FLOAT32, "w", 1,
                             sensor_msgs::PointField::FLOAT32, "wall", 1, sensor_msgs::PointField::FLOAT32, "table_u", 1,
                             sensor_msgs::PointField::FLOAT32, "table_v", 1, sensor_msgs::PointField::FLOAT32, "table_w", 1,
                             sensor_msgs::PointField::FLOAT32, "difference", 1, sensor_msgs::PointField::FLOAT32);
    mod.resize(s.position.size());
    sensor_msgs::PointCloud2Iterator<float> x(cloud, "x"), sp(cloud, "speed"), u(cloud, "u"), wall(cloud, "wall"), table(cloud, "table_u"),
        difference(cloud, "difference");
    for (std::size_t i = 0; i < s.position.size(); ++i, ++x, ++sp, ++u, ++wall, ++table, ++difference) {
      x[0] = static_cast<float>(s.position[i].x());
      x[1] = static_cast<float>(s.position[i].y());
      x[2] = static_cast<float>(s.position[i].z());
      sp[0] = static_cast<float>(s.velocity[i].norm());
      u[0] = static_cast<float>(s.velocity[i].x());
      u[1] = static_cast<float>(s.velocity[i].y());
      u[2] = static_cast<float>(s.velocity[i].z());
      wall[0] = s.wall[i];
      for (int d = 0; d < 3; ++d) table[d] = static_cast<float>(s.undisturbed[i][d]);
      difference[0] = static_cast<float>((s.velocity[i] - s.undisturbed[i]).norm());
    }
    slice_.publish(cloud);
  }

  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& stat) {
    if (!fluid_) {
      stat.summary(diagnostic_msgs::DiagnosticStatus::ERROR, "not started");
      return;
    }
    if (diverged_)
      stat.summary(diagnostic_msgs::DiagnosticStatus::ERROR, "stopped: " + failure_);
    else if (max_mach_ > 0.5)
      stat.summary(diagnostic_msgs::DiagnosticStatus::WARN, "lattice Mach above 0.5");
    else
      stat.summary(diagnostic_msgs::DiagnosticStatus::OK, "running");
    stat.add("requests served", served_);
    stat.add("wake table from", wake_source_);
    stat.add("LBM steps", std::lround(fluid_->domain().time() / fluid_->domain().time_step()));
    stat.add("fluid time (s)", fluid_->domain().time());
    stat.add("LBM time step (s)", fluid_->domain().time_step());
    stat.add("duplicate requests (answered again, not served)", duplicates_);
    stat.add("LBM steps dropped to catch up (real time)", fluid_->dropped_steps());
    stat.add("LBM step (ms)", step_ms_);
    stat.add("MLUPS", mlups_);
    stat.add("max lattice Mach (slice)", max_mach_);
    stat.add("wall cells", fluid_->domain().wall_cells());
    stat.add("ship voxelisations", fluid_->voxelisations());
    stat.add("face refreshes", fluid_->face_refreshes());
    // where a real-time job's time goes (docs/benchmarks.md at 193c1b4, "ROS layer in real time"): its LBM work,
    // and its wait between the flight model's request and its handling here
    stat.add("job (ms), p50 of the last 1000", percentile(job_ms_, 0.5));
    stat.add("job (ms), p99 of the last 1000", percentile(job_ms_, 0.99));
    if (realtime_) stat.add("request to its handling (ms), p99 of the last 1000", percentile(delay_ms_, 0.99));
  }

  static constexpr std::size_t kJobWindow = 1000;
  static void remember(std::deque<double>& d, double v) {
    d.push_back(v);
    if (d.size() > kJobWindow) d.pop_front();
  }
  static double percentile(std::deque<double> d, double q) {
    if (d.empty()) return 0.0;
    const auto k = static_cast<std::ptrdiff_t>(std::ceil(q * static_cast<double>(d.size()))) - 1;
    std::nth_element(d.begin(), d.begin() + std::max<std::ptrdiff_t>(k, 0), d.end());
    return d[static_cast<std::size_t>(std::max<std::ptrdiff_t>(k, 0))];
  }

  lrm::ApproachConfig cfg_;
  flight::HelicopterParameters params_;
  std::string wake_source_ = "file";
  bool realtime_ = false;
  std::atomic<bool> failed_{false};  // set by the solver's thread too
  std::unique_ptr<lrm::ApproachFluid> fluid_;
  double slice_interval_ = 0.1, clock_offset_ = 1.0, next_slice_ = 0, step_ms_ = 0, mlups_ = 0, max_mach_ = 0;
  SimEpoch epoch_;
  int slice_normal_ = 1;
  long served_ = 0, duplicates_ = 0;
  int answer_subscribers_ = 1;                    // rotor/inflow: the flight model, and a recorder
  ship_lrm::RotorForces::ConstPtr last_request_;  // the last request served, and its answer
  ship_lrm::RotorInflow last_answer_;
  bool diverged_ = false;
  std::string failure_;
  std::deque<double> job_ms_, delay_ms_;  // the last kJobWindow jobs served, requests received
  ros::Publisher inflow_, slice_, box_;
  ros::CallbackQueue jobs_;  // rotor/forces, served by thread_ (declared before forces_: outlives it)
  ros::Subscriber forces_, info_;
  tf2_ros::TransformBroadcaster tf_;
  diagnostic_updater::Updater diagnostics_;
  std::atomic<bool> stop_{false};
  std::thread thread_;  // builds the domain, then serves jobs_
};

}  // namespace ship_lrm::ros_layer

PLUGINLIB_EXPORT_CLASS(ship_lrm::ros_layer::LrmSolverNodelet, nodelet::Nodelet)
