// The fluid side of the ship approach (see approach_fluid.hpp).
#include "ship_lrm/lrm/approach_fluid.hpp"

#include <Eigen/Geometry>

#include "ship_lrm/lrm/walls.hpp"

namespace ship_lrm::lrm {

ApproachFluid::ApproachFluid(const ApproachConfig& cfg, const flight::HelicopterParameters& params, std::shared_ptr<wake::WakeTable> table)
    : table_(table ? std::move(table) : open_approach_table(cfg)),
      lrm_(approach_lrm_config(cfg, params, table_->info()), 0.0),  // the start-up is part of the run (thesis 9.1)
      rotor_forces_on_fluid_(cfg.rotor_forces_on_fluid) {
  if (cfg.fuselage) lrm_.domain().add_wall(std::make_shared<Fuselage>());
  if (cfg.ship_walls) {
    const ApproachShip ship = approach_ship(cfg, table_->info());
    walls_ = std::make_unique<ShipInDomain>(ship.geometry, ship.motion);
  }
  if (cfg.wake) feed_ = std::make_unique<WakeFaceFeed>(table_);
}

void ApproachFluid::place(double table_time, const DomainPose& pose) {
  if (placed_ && table_time == placed_time_) return;
  if (walls_) walls_->apply(lrm_.domain(), table_time, pose);
  if (feed_ && feed_->apply(lrm_.domain(), table_time, pose)) ++face_refreshes_;
  placed_ = true;
  placed_time_ = table_time;
  placed_pose_ = pose;
}

namespace {
DomainPose between(const DomainPose& a, const DomainPose& b, double f) {
  DomainPose p;
  p.hub = a.hub + f * (b.hub - a.hub);
  p.rotation = Eigen::Quaterniond(a.rotation).slerp(f, Eigen::Quaterniond(b.rotation)).toRotationMatrix();
  p.hub_velocity = a.hub_velocity + f * (b.hub_velocity - a.hub_velocity);
  p.omega = a.omega + f * (b.omega - a.omega);
  return p;
}
// The rotor's motion between two requests; the loads stay the newer request's (the job's).
rotor::RotorDiskState between(const rotor::RotorDiskState& a, const rotor::RotorDiskState& b, double f) {
  rotor::RotorDiskState s = b;
  s.time = a.time + f * (b.time - a.time);
  s.hub_velocity = a.hub_velocity + f * (b.hub_velocity - a.hub_velocity);
  s.body_rate = a.body_rate + f * (b.body_rate - a.body_rate);
  return s;
}
}  // namespace

rotor::RotorDiskState ApproachFluid::loads(const rotor::RotorDiskState& s) const {
  if (rotor_forces_on_fluid_) return s;
  rotor::RotorDiskState off = s;
  off.aero_force = Vec3::Zero();
  off.aero_moment = Vec3::Zero();
  off.harmonics = rotor::RotorForceHarmonics();
  return off;
}

rotor::RotorInflow ApproachFluid::serve(const InflowRequest& request) {
  const long steps = request.kind == InflowRequest::Kind::Advance ? lrm_.steps_due(request.dt) : 0;
  if (steps <= 1 || !placed_) {
    place(request.table_time, request.pose);
    if (request.kind == InflowRequest::Kind::Reset)
      lrm_.reset(loads(request.state));
    else
      lrm_.advance(loads(request.state), request.dt);
  } else {
    const double t0 = placed_time_;
    const DomainPose pose0 = placed_pose_;
    const rotor::RotorDiskState state0 = last_state_;
    double done = 0;
    long first = 1;
    const long limit = lrm_.catch_up_limit();
    if (limit > 0 && steps > limit) {  // a real-time backlog: drop all but the newest `limit` steps
      first = steps - limit + 1;
      done = static_cast<double>(first - 1) / static_cast<double>(steps) * request.dt;
      lrm_.skip(done);
    }
    for (long k = first; k <= steps; ++k) {
      const double f = static_cast<double>(k) / static_cast<double>(steps);
      place(t0 + f * (request.table_time - t0), between(pose0, request.pose, f));
      const double dt = f * request.dt - done;  // the last one ends exactly at request.dt (f = 1)
      lrm_.advance(loads(between(state0, request.state, f)), dt);
      done += dt;
    }
  }
  last_state_ = request.state;
  served_wall_cells_.store(lrm_.domain().wall_cells(), std::memory_order_relaxed);
  served_voxelisations_.store(voxelisations(), std::memory_order_relaxed);
  served_face_refreshes_.store(face_refreshes_, std::memory_order_relaxed);
  served_wall_changes_.store(lrm_.domain().rebuilds(), std::memory_order_relaxed);
  served_face_restarts_.store(lrm_.domain().face_restarts(), std::memory_order_relaxed);
  served_wall_seconds_.store(lrm_.domain().wall_seconds(), std::memory_order_relaxed);
  return lrm_.inflow();
}

ApproachFluid::Counts ApproachFluid::counts() const {
  Counts c;
  c.wall_cells = served_wall_cells_.load(std::memory_order_relaxed);
  c.voxelisations = served_voxelisations_.load(std::memory_order_relaxed);
  c.face_refreshes = served_face_refreshes_.load(std::memory_order_relaxed);
  c.wall_changes = served_wall_changes_.load(std::memory_order_relaxed);
  c.face_restarts = served_face_restarts_.load(std::memory_order_relaxed);
  c.wall_seconds = served_wall_seconds_.load(std::memory_order_relaxed);
  return c;
}

}  // namespace ship_lrm::lrm
