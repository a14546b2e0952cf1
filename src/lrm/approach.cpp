// The ship approach of thesis 9.1 (see approach.hpp).
#include "ship_lrm/lrm/approach.hpp"

#include <chrono>
#include <cmath>
#include <sstream>

namespace ship_lrm::lrm {
namespace {
std::string num(double v) {
  std::ostringstream o;
  o << v;
  return o.str();
}
}  // namespace

double ApproachPath::speed_at(double t) const {
  if (t <= decelerate_at) return speed;
  if (t >= hover_at) return 0.0;
  return speed * (hover_at - t) / (hover_at - decelerate_at);
}

double ApproachPath::distance_at(double t) const {
  const double cruise = speed * std::min(std::max(t, 0.0), decelerate_at);
  const double s = std::min(std::max(t, decelerate_at), hover_at) - decelerate_at;  // time into the deceleration
  const double braking = hover_at > decelerate_at ? speed * (s - 0.5 * s * s / (hover_at - decelerate_at)) : 0.0;
  return start_distance - cruise - braking;
}

void ApproachPath::validate() const {
  if (!std::isfinite(start_distance)) throw lbm::ConfigError("approach: the start distance must be finite");
  if (!(height > 0) || !std::isfinite(height))
    throw lbm::ConfigError("approach: the height above the deck must be > 0 m, got " + num(height));
  if (!(speed >= 0) || !std::isfinite(speed)) throw lbm::ConfigError("approach: the speed must be >= 0 m/s, got " + num(speed));
  if (!std::isfinite(lateral)) throw lbm::ConfigError("approach: the lateral offset must be finite");
  if (!(decelerate_at >= 0) || !(hover_at >= decelerate_at) || !std::isfinite(hover_at))
    throw lbm::ConfigError("approach: need 0 <= decelerate-at <= hover-at, got " + num(decelerate_at) + " and " + num(hover_at));
}

ShipApproach::ShipApproach(const ApproachConfig& cfg, const flight::HelicopterParameters& params) : cfg_(cfg) {
  cfg_.path.validate();
  if (!(cfg_.duration > 0) || !std::isfinite(cfg_.duration)) throw lbm::ConfigError("approach: the duration must be > 0 s");
  if (!(cfg_.startup >= 0) || !(cfg_.startup < cfg_.duration))
    throw lbm::ConfigError("approach: the start-up must lie in [0, duration), got " + num(cfg_.startup));
  if (cfg_.inflow != "lrm" && cfg_.inflow != "pitt_peters")
    throw lbm::ConfigError("approach: inflow must be 'lrm' or 'pitt_peters', got '" + cfg_.inflow + "'");
  if (!(cfg_.table_offset >= 0)) throw lbm::ConfigError("approach: the table offset must be >= 0 s");
  table_ = std::make_shared<wake::WakeTable>(cfg_.table);
  const wake::WakeTableInfo& info = table_->info();
  if (info.scale != "full")
    throw lbm::ConfigError("approach: the wake table '" + cfg_.table + "' is of a " + info.scale +
                           "-scale ship; the Bo 105 needs a full-scale table (ship_lrm wake --scale full)");
  const double need = info.start_time + cfg_.table_offset + cfg_.duration;
  if (need > info.end_time() + 1e-6)
    throw lbm::ConfigError("approach: the wake table '" + cfg_.table + "' covers " + num(info.end_time() - info.start_time) +
                           " s; the approach needs " + num(cfg_.table_offset + cfg_.duration) +
                           " s (shorten --duration or make a longer table with ship_lrm wake --duration)");
  // the ship and its motion from the table's attributes: the walls move as the wake's ship did
  try {
    ship_ = wake::make_ship(info.ship, info.scale);
    motion_ = wake::make_motion(info.motion, wake::ship_scale(info.scale), wake::motion_centre(ship_->datum()));
  } catch (const std::exception& e) {
    throw lbm::ConfigError("approach: cannot rebuild the ship of wake table '" + cfg_.table + "' (ship '" + info.ship + "', motion '" +
                           info.motion + "'): " + e.what());
  }
  spot_ = wake::landing_spot(ship_->datum());
  const Vec3 wind(info.free_stream[0], info.free_stream[1], info.free_stream[2]);
  const double airspeed = cfg_.trim_speed > 0 ? cfg_.trim_speed : (Vec3(cfg_.path.speed, 0, 0) - wind).norm();

  // fixed controls: the Pitt-Peters trim at the approach's airspeed (thesis 9.1: 25.58 m/s)
  {
    flight::Helicopter pp(params);
    flight::TrimTarget target;
    target.speed = airspeed;
    trim_ = flight::trim(pp, target);
    if (!trim_.converged)
      throw lbm::ConfigError("approach: the Pitt-Peters trim at " + num(airspeed) + " m/s did not converge (" + trim_.message + ")");
  }
  attitude_ = flight::RigidBodyState::from_euler(trim_.roll, trim_.pitch, 0.0);

  std::unique_ptr<rotor::InflowModel> inflow;
  if (cfg_.inflow == "lrm") {
    LrmConfig c = cfg_.lrm;
    c.radius = params.main_rotor.radius;
    c.density = params.density;
    c = config_for_stream(c, cfg_.lattice_margin * (wind.norm() + cfg_.path.speed));
    auto model = std::make_unique<LrmInflow>(c, 0.0);  // the start-up period is part of the run (thesis 9.1)
    lrm_ = model.get();
    inflow = std::move(model);
    if (cfg_.fuselage) lrm_->domain().add_wall(std::make_shared<Fuselage>());
    if (cfg_.ship_walls) walls_ = std::make_unique<ShipInDomain>(ship_, motion_);
    if (cfg_.wake) feed_ = std::make_unique<WakeFaceFeed>(table_);
  }
  heli_ = std::make_unique<flight::Helicopter>(params, std::move(inflow));
  heli_->set_controls(trim_.controls);
  heli_->set_wind(wind);
  heli_->set_body_held(true);  // moved along the path (a whirl tower with a fuselage, thesis 9.1)
  place(0.0, true);
  record();
}

DomainPose ShipApproach::domain_pose(double t) const {
  const Vec3 cg(spot_.x() - cfg_.path.distance_at(t), spot_.y() + cfg_.path.lateral, spot_.z() - cfg_.path.height);
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
  const double table_time = table_->info().start_time + cfg_.table_offset + t;
  if (lrm_) {
    LrmDomain& domain = lrm_->domain();
    if (walls_) walls_->apply(domain, table_time, pose);
    if (feed_ && feed_->apply(domain, table_time, pose)) ++sample_.face_refreshes;
  } else if (cfg_.wake) {
    // Pitt-Peters: the wake's air at the hub is the wind the whole helicopter flies in
    hub_xyz_.assign(pose.hub.data(), pose.hub.data() + 3);
    table_->sample(table_time, hub_xyz_, hub_air_);
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
  const double table_time = table_->info().start_time + cfg_.table_offset + t;
  const wake::ShipPlacement place = motion_->placement(table_time);
  s.height_above_deck = spot_.z() - place.to_body(s.cg).z();  // z down: the deck at the spot's level
  const wake::ShipPose ship = motion_->pose(table_time);
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
  if (lrm_) s.wall_cells = lrm_->domain().wall_cells();
  if (walls_) s.voxelisations = walls_->voxelisations();
}

}  // namespace ship_lrm::lrm
