// Feeding the LRM's faces from a ship-wake table (see wake_feed.hpp).
#include "ship_lrm/lrm/wake_feed.hpp"

#include <chrono>
#include <sstream>

namespace ship_lrm::lrm {

WakeFaceFeed::WakeFaceFeed(std::shared_ptr<wake::WakeTable> table) : table_(std::move(table)) {
  if (!table_) throw lbm::ConfigError("WakeFaceFeed: no wake table");
}

bool WakeFaceFeed::apply(LrmDomain& domain, double t, const Pose& pose, bool force) {
  const double dx = domain.units().dx();
  const double edge = dx * domain.cells_per_edge();
  if (&domain != domain_ || domain.rebuilds() != rebuilds_ || positions_.empty()) {
    positions_ = domain.face_positions();  // changes only when walls moved through a face
    domain_ = &domain;
    rebuilds_ = domain.rebuilds();
    force = true;
  }
  if (!force && fed_) {
    const double turned = Eigen::AngleAxisd(last_.rotation.transpose() * pose.rotation).angle();
    if (std::abs(t - last_t_) < 0.25 * table_->info().frame_interval && (pose.hub - last_.hub).norm() < 0.25 * dx &&
        turned * 0.5 * edge < 0.25 * dx &&
        (pose.hub_velocity - last_.hub_velocity).norm() < 0.01 * std::abs(table_->info().free_stream[0]) + 1e-9)
      return false;
  }
  fed_ = true;
  last_t_ = t;
  last_ = pose;
  const std::vector<Vec3>& r = positions_;
  xyz_.resize(3 * r.size());
  for (std::size_t k = 0; k < r.size(); ++k) {
    const Vec3 p = pose.hub + pose.rotation * r[k];
    for (int d = 0; d < 3; ++d) xyz_[3 * k + d] = p[d];
  }
  table_->sample(t, xyz_, samples_);
  std::vector<Vec3> air(r.size());
  const Mat3 to_mr = pose.rotation.transpose();
  for (std::size_t k = 0; k < r.size(); ++k) {
    const Vec3 u(samples_[k].u[0], samples_[k].u[1], samples_[k].u[2]);
    air[k] = to_mr * (u - pose.hub_velocity);
  }
  domain.set_face_air(std::move(air));
  return true;
}

std::string WakeFeedBenchmark::to_json() const {
  std::ostringstream o;
  o << "{\"backend\": \"" << backend << "\", \"N\": " << nodes << ", \"cells_per_edge\": " << cells_per_edge << ", \"steps\": " << steps
    << ", \"refreshes\": " << refreshes << ", \"boundary_cells\": " << boundary_cells << ", \"window_loads\": " << window_loads
    << ", \"step_s\": " << step_seconds << ", \"feed_s\": " << feed_seconds << ", \"feed_fraction\": " << feed_fraction() << "}";
  return o.str();
}

WakeFeedBenchmark run_wake_feed_benchmark(const std::string& table, const LrmConfig& cfg, int steps, double speed, double height) {
  if (steps < 1) throw lbm::ConfigError("bench wake: steps must be >= 1");
  auto t = std::make_shared<wake::WakeTable>(table);
  const auto& info = t->info();
  LrmConfig c = config_for_stream(cfg, std::abs(info.free_stream[0]) + speed);
  LrmDomain domain(c);
  WakeFaceFeed feed(t);
  WakeFaceFeed::Pose pose;
  // start from the undisturbed stream relative to the hub, not from rest (no impulsive start)
  domain.set_stream(Vec3(info.free_stream[0] - speed, info.free_stream[1], info.free_stream[2]));
  domain.restart_flow();
  const double t0 = info.start_time;
  using Clock = std::chrono::steady_clock;
  double feed_s = 0, step_s = 0;
  std::size_t refreshes = 0;
  const int warm = 3;
  for (int s = -warm; s < steps; ++s) {
    const double time = t0 + std::max(s, 0) * domain.time_step();
    pose.hub = Vec3(-12.75 * 1.0 + speed * (time - t0) - 40.0, 0.0, -height);  // from 40 m behind the spot
    pose.hub_velocity = Vec3(speed, 0, 0);
    const auto a = Clock::now();
    refreshes += feed.apply(domain, time, pose) && s >= 0;
    domain.solver().synchronize();
    const auto b = Clock::now();
    domain.step(1);
    domain.solver().synchronize();
    const auto e = Clock::now();
    if (s >= 0) {
      feed_s += std::chrono::duration<double>(b - a).count();
      step_s += std::chrono::duration<double>(e - b).count();
    }
  }
  WakeFeedBenchmark r;
  r.backend = domain.solver().backend_name();
  r.nodes = c.nodes;
  r.cells_per_edge = domain.cells_per_edge();
  r.steps = steps;
  r.boundary_cells = domain.face_positions().size();
  r.window_loads = t->window_loads();
  r.refreshes = refreshes;
  r.step_seconds = step_s / steps;
  r.feed_seconds = feed_s / steps;
  return r;
}

}  // namespace ship_lrm::lrm
