// The ship approach of thesis 9.1 (see approach.hpp).
#include "ship_lrm/lrm/approach.hpp"

#include <chrono>
#include <cmath>
#include <sstream>

namespace ship_lrm::lrm {

ShipApproach::ShipApproach(const ApproachConfig& cfg, const flight::HelicopterParameters& params, std::shared_ptr<InflowLink> link,
                           std::optional<RealTimeMode> realtime)
    : cfg_(cfg) {
  table_ = open_approach_table(cfg_);  // validates cfg_
  const wake::WakeTableInfo& info = table_->info();
  ship_ = approach_ship(cfg_, info);
  const Vec3 wind = free_stream(info);
  const double airspeed = cfg_.trim_speed > 0 ? cfg_.trim_speed : (Vec3(cfg_.path.speed, 0, 0) - wind).norm();

  // fixed controls: the Pitt-Peters trim at the approach's airspeed (thesis 9.1: 25.58 m/s)
  {
    flight::Helicopter pp(params);
    flight::TrimTarget target;
    target.speed = airspeed;
    trim_ = flight::trim(pp, target);
    if (!trim_.converged) {
      std::ostringstream m;
      m << "approach: the Pitt-Peters trim at " << airspeed << " m/s did not converge (" << trim_.message << ")";
      throw lbm::ConfigError(m.str());
    }
  }
  attitude_ = flight::RigidBodyState::from_euler(trim_.roll, trim_.pitch, 0.0);

  std::unique_ptr<rotor::InflowModel> inflow;
  if (cfg_.inflow == "lrm") {
    if (!link) {
      fluid_ = std::make_shared<ApproachFluid>(cfg_, params, table_);
      if (realtime) fluid_->set_catch_up_limit(kRealTimeCatchUpSteps);
      link = std::make_shared<DirectLink>(fluid_);
    }
    auto model = std::make_unique<LinkedInflow>(std::move(link), [this](double t, DomainPose& pose, double& table_t) {
      pose = domain_pose(t);
      table_t = table_time(t);
    });
    linked_ = model.get();
    inflow = std::move(model);
    if (realtime) {
      // the LRM's own step sets the pipeline's lag; the budget is replaced by each step's deadline
      const double lbm_dt = lattice_units(approach_lrm_config(cfg_, params, table_->info())).dt();
      auto rt = std::make_unique<RealTimeInflow>(std::move(inflow), lbm_dt, 1.0, *realtime);
      realtime_ = rt.get();
      inflow = std::move(rt);
    }
  }
  heli_ = std::make_unique<flight::Helicopter>(params, std::move(inflow));
  heli_->set_controls(trim_.controls);
  heli_->set_wind(wind);
  heli_->set_body_held(true);  // moved along the path (a whirl tower with a fuselage, thesis 9.1)
  place(0.0, true);
  record();
}

DomainPose ShipApproach::domain_pose(double t) const {
  const Vec3& spot = ship_.spot;
  const Vec3 cg(spot.x() - cfg_.path.distance_at(t), spot.y() + cfg_.path.lateral, spot.z() - cfg_.path.height);
  DomainPose pose;
  pose.hub = cg + attitude_ * heli_->parameters().main_rotor.hub_position;
  pose.rotation = attitude_.toRotationMatrix() * heli_->mr_to_body();
  pose.hub_velocity = Vec3(cfg_.path.speed_at(t), 0, 0);
  return pose;
}

void ShipApproach::place(double t, bool start) {
  const DomainPose pose = domain_pose(t);
  flight::RigidBodyState body;
  body.position = pose.hub - attitude_ * heli_->parameters().main_rotor.hub_position;
  body.attitude = attitude_;
  body.velocity = attitude_.conjugate() * pose.hub_velocity;
  if (fluid_ && !realtime_) {
    // (a linked fluid side, and one in the real-time LRM thread, places itself when the next request comes)
    fluid_->place(table_time(t), pose);
  } else if (!linked_ && cfg_.wake) {
    // Pitt-Peters: the wake's air at the hub is the wind the whole helicopter flies in
    hub_xyz_.assign(pose.hub.data(), pose.hub.data() + 3);
    table_->sample(table_time(t), hub_xyz_, hub_air_);
    heli_->set_wind(Vec3(hub_air_[0].u[0], hub_air_[0].u[1], hub_air_[0].u[2]));
  }
  if (start)
    heli_->reset(body);
  else
    heli_->set_body(body);
}

void ShipApproach::step() {
  const auto start = std::chrono::steady_clock::now();
  heli_->step();
  place(heli_->time(), false);
  wall_seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  record();
}

bool ShipApproach::done() const { return heli_->time() >= cfg_.duration - 0.5 * heli_->time_step(); }

void ShipApproach::record() {
  const double t = heli_->time();
  const auto& p = heli_->parameters();
  const auto& o = heli_->outputs();
  ApproachSample& s = sample_;
  s.time = t;
  s.cg = heli_->body().position;
  s.distance = cfg_.path.distance_at(t);
  s.speed = cfg_.path.speed_at(t);
  const wake::ShipPlacement place = ship_placement(t);
  s.height_above_deck = ship_.spot.z() - place.to_body(s.cg).z();  // z down: the deck at the spot's level
  const wake::ShipPose ship = ship_.motion->pose(table_time(t));
  s.ship_heave = ship.heave;
  s.ship_pitch = ship.pitch;
  const double R = p.main_rotor.radius, tip = p.main_rotor.rotor_speed * R;
  const double q = p.density * M_PI * R * R * tip * tip;
  s.thrust = -o.rotor.aero_force.z();
  s.ct = s.thrust / q;
  s.cmx = o.rotor.aero_moment.x() / (q * R);
  s.cmy = o.rotor.aero_moment.y() / (q * R);
  s.main_power = o.main_power;
  s.inflow_mean = o.inflow.mean;
  if (fluid_ && !realtime_) {  // (in real time the LRM thread owns the domain)
    s.wall_cells = fluid_->domain().wall_cells();
    s.voxelisations = fluid_->voxelisations();
    s.face_refreshes = fluid_->face_refreshes();
  }
}

}  // namespace ship_lrm::lrm
