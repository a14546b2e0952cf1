// Feeding the LRM's faces from a ship-wake table (see wake_feed.hpp).
#include "ship_lrm/lrm/wake_feed.hpp"

#include <algorithm>
#include <chrono>
#include <limits>
#include <sstream>

namespace ship_lrm::lrm {

WakeFaceFeed::WakeFaceFeed(std::shared_ptr<wake::WakeTable> table) : table_(std::move(table)) {
  if (!table_) throw ConfigError("WakeFaceFeed: no wake table");
}

bool WakeFaceFeed::apply(LrmDomain& domain, double t, const Pose& pose, bool force) {
  const double dx = domain.units().dx();
  const double edge = dx * domain.cells_per_edge();
  if (&domain != domain_ || !domain.has_face_grid()) {
    domain_ = &domain;
    force = true;
  }
  if (!force && fed_) {
    const double turned = Eigen::AngleAxisd(last_.rotation.transpose() * pose.rotation).angle();
    if (std::abs(t - last_t_) < 0.25 * table_->info().frame_interval && (pose.hub - last_.hub).norm() < 0.25 * dx &&
        turned * 0.5 * edge < 0.25 * dx &&
        (pose.hub_velocity - last_.hub_velocity).norm() < 0.01 * std::abs(table_->info().free_stream[0]) + 1e-9)
      return false;
  }
  // the box of the domain's cells in the table's frame: the rotated cube's corners
  const double lo_r = -domain.centre() * dx, hi_r = (domain.cells_per_edge() - 1 - domain.centre()) * dx;
  std::array<double, 3> lo{}, hi{};
  lo.fill(std::numeric_limits<double>::infinity());
  hi.fill(-std::numeric_limits<double>::infinity());
  for (int c = 0; c < 8; ++c) {
    const Vec3 p = pose.hub + pose.rotation * Vec3(c & 1 ? hi_r : lo_r, c & 2 ? hi_r : lo_r, c & 4 ? hi_r : lo_r);
    for (int d = 0; d < 3; ++d) {
      lo[d] = std::min(lo[d], p[d]);
      hi[d] = std::max(hi[d], p[d]);
    }
  }
  const wake::WakeTable::Frames f = table_->frames(t, lo, hi);
  domain.set_face_grid(f.window, f.serial, f.grid, pose.hub, pose.rotation, pose.hub_velocity);
  fed_ = true;
  last_t_ = t;
  last_ = pose;
  return true;
}

std::string WakeFeedBenchmark::to_json() const {
  std::ostringstream o;
  o << "{\"backend\": \"" << backend << "\", \"N\": " << nodes << ", \"cells_per_edge\": " << cells_per_edge << ", \"steps\": " << steps
    << ", \"refreshes\": " << refreshes << ", \"boundary_cells\": " << boundary_cells << ", \"window_loads\": " << window_loads
    << ", \"read_ahead_hits\": " << read_ahead_hits << ", \"step_s\": " << step_seconds << ", \"feed_s\": " << feed_seconds
    << ", \"feed_fraction\": " << feed_fraction() << ", \"loop_fed_step_s\": " << loop_fed_seconds
    << ", \"loop_step_s\": " << loop_alone_seconds << ", \"loop_feed_fraction\": " << loop_feed_fraction() << "}";
  return o.str();
}

WakeFeedBenchmark run_wake_feed_benchmark(const std::string& table, const LrmConfig& cfg, int steps, double speed, double height) {
  if (steps < 1) throw ConfigError("bench wake: steps must be >= 1");
  auto t = std::make_shared<wake::WakeTable>(table);
  const auto& info = t->info();
  LrmConfig c = config_for_stream(cfg, std::abs(info.free_stream[0]) + speed);
  LrmDomain domain(c);
  WakeFaceFeed feed(t);
  // start from the undisturbed stream relative to the hub, not from rest (no impulsive start)
  domain.set_stream(Vec3(info.free_stream[0] - speed, info.free_stream[1], info.free_stream[2]));
  domain.restart_flow();
  const double t0 = info.start_time;
  using Clock = std::chrono::steady_clock;
  double feed_s = 0, step_s = 0;
  std::size_t refreshes = 0;
  const int warm = 3;
  const auto pose_at = [&](double time) {
    WakeFaceFeed::Pose pose;
    pose.hub = Vec3(-12.75 * 1.0 + speed * (time - t0) - 40.0, 0.0, -height);  // from 40 m behind the spot
    pose.hub_velocity = Vec3(speed, 0, 0);
    return pose;
  };
  for (int s = -warm; s < steps; ++s) {
    const double time = t0 + std::max(s, 0) * domain.time_step();
    const WakeFaceFeed::Pose pose = pose_at(time);
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
  // in the loop: fed and stepped without a wait in between, against the steps alone (faces held),
  // alternating, the best of two each; the flight goes on where the timed steps above ended
  double fed = std::numeric_limits<double>::infinity(), alone = fed;
  long k = steps;
  for (int rep = 0; rep < 2; ++rep) {
    auto a = Clock::now();
    for (int s = 0; s < steps; ++s, ++k) {
      const double time = t0 + k * domain.time_step();
      feed.apply(domain, time, pose_at(time));
      domain.step(1);
    }
    domain.solver().synchronize();
    fed = std::min(fed, std::chrono::duration<double>(Clock::now() - a).count() / steps);
    a = Clock::now();
    domain.step(steps);
    domain.solver().synchronize();
    alone = std::min(alone, std::chrono::duration<double>(Clock::now() - a).count() / steps);
    k += steps;
  }
  WakeFeedBenchmark r;
  r.loop_fed_seconds = fed;
  r.loop_alone_seconds = alone;
  r.backend = domain.solver().backend_name();
  r.nodes = c.nodes;
  r.cells_per_edge = domain.cells_per_edge();
  r.steps = steps;
  r.boundary_cells = domain.solver().lattice().boundary_cells().size();
  r.window_loads = t->window_loads();
  r.read_ahead_hits = t->window_read_ahead_hits();
  r.refreshes = refreshes;
  r.step_seconds = step_s / steps;
  r.feed_seconds = feed_s / steps;
  return r;
}

}  // namespace ship_lrm::lrm
