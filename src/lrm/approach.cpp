// The ship approach of thesis 9.1 (see approach.hpp).
#include "ship_lrm/lrm/approach.hpp"

#include <algorithm>
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
      throw ConfigError(m.str());
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
    // (in real time this runs in the LRM thread: it reads only the posted state and the set-up)
    auto model = std::make_unique<LinkedInflow>(std::move(link), [this](const rotor::RotorDiskState& s, DomainPose& pose, double& table_t) {
      pose = cfg_.free_flight ? domain_pose(s) : domain_pose(s.time);
      table_t = table_time(s.time);
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
  // held: moved along the path (a whirl tower with a fuselage, thesis 9.1); free flight: held during
  // the start-up too (the blades and the LRM's wake settle), then flown from there
  heli_->set_body_held(!released());
  place(0.0, true, true);
  check_contact();
  if (!end_reason_.empty()) throw ConfigError("approach: the start puts the landing gear into the ship or the sea (" + end_reason_ + ")");
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

DomainPose ShipApproach::domain_pose(const rotor::RotorDiskState& s) const {
  DomainPose pose;
  pose.hub = s.hub_position;
  pose.rotation = s.mr_to_world;
  pose.hub_velocity = s.hub_world_velocity;
  pose.omega = s.body_rate;
  return pose;
}

void ShipApproach::place(double t, bool start, bool on_path) {
  // on the path, or where the helicopter flew to
  const DomainPose pose = on_path ? domain_pose(t) : domain_pose(heli_->disk_motion());
  if (fluid_ && !realtime_) {
    // (a linked fluid side, and one in the real-time LRM thread, places itself when the next request comes)
    fluid_->place(table_time(t), pose);
  } else if (!linked_ && cfg_.wake) {
    // Pitt-Peters: the wake's air at the hub is the wind the whole helicopter flies in
    hub_xyz_.assign(pose.hub.data(), pose.hub.data() + 3);
    table_->sample(table_time(t), hub_xyz_, hub_air_);
    heli_->set_wind(Vec3(hub_air_[0].u[0], hub_air_[0].u[1], hub_air_[0].u[2]));
  }
  if (!on_path) return;
  flight::RigidBodyState body;
  body.position = pose.hub - attitude_ * heli_->parameters().main_rotor.hub_position;
  body.attitude = attitude_;
  body.velocity = attitude_.conjugate() * pose.hub_velocity;
  if (start)
    heli_->reset(body);
  else
    heli_->set_body(body);
}

void ShipApproach::step() {
  const auto start = std::chrono::steady_clock::now();
  const bool held = !released();
  heli_->set_body_held(held);
  try {
    heli_->step();
    if (cfg_.free_flight && held) trim_controls();
    place(heli_->time(), false, held);
  } catch (const WallOnRotorDisk& e) {
    if (held) throw;  // on the path: the set-up put the rotor into a wall
    // flown there (a bank steep enough puts a blade tip below the skids): the flight ends, it is no
    // error of the input; the step was not completed, so it is not recorded
    const double t = heli_->time();
    std::ostringstream m;
    m.precision(3);
    m << std::fixed << "struck the " << (e.wall() == "ground" ? "sea" : e.wall()) << " with the rotor at t = " << t << " s, "
      << ship_.spot.x() - heli_->body().position.x() << " m behind the landing spot (the LRM's " << e.wall()
      << " wall reached the rotor disk's cells)";
    end_reason_ = m.str();
    wall_seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return;
  }
  check_contact();
  wall_seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  record();
}

void ShipApproach::trim_controls() {
  const auto& p = heli_->parameters();
  const auto& o = heli_->outputs();
  const double revolution = 2 * M_PI / p.main_rotor.rotor_speed;
  // the blades start at zero flap: the trim lets its first evaluation settle this long
  if (heli_->time() <= (flight::TrimOptions{}.settle_revolutions + 3) * revolution) return;
  // the trim's residual (flight/trim.cpp): accelerations / g and angular accelerations, revolution means
  residual_sum_.head<3>() += o.acceleration / p.mass.gravity * heli_->time_step();
  residual_sum_.tail<3>() += o.angular_acceleration * heli_->time_step();
  residual_time_ += heli_->time_step();
  if (residual_time_ < revolution - 0.5 * heli_->time_step()) return;
  const Eigen::Matrix<double, 6, 1> r = residual_sum_ / residual_time_;
  residual_sum_.setZero();
  residual_time_ = 0;
  // Newton step with the Pitt-Peters trim's Jacobian for the controls against heave, roll, pitch and
  // yaw (the held attitude cannot answer surge and sway), half of it (the LRM's inflow answers slower
  // and differently), at most 2 deg per revolution, as the trim limits its steps.
  const Eigen::Matrix4d j = trim_.jacobian.block<4, 4>(2, 0);
  const Eigen::Vector4d r4 = r.tail<4>();
  Eigen::Vector4d dx = -0.5 * j.fullPivLu().solve(r4);
  if (!dx.allFinite()) return;  // no Jacobian (a trim that converged without one): keep the controls
  const double lim = dx.cwiseAbs().maxCoeff() / 0.035;
  if (lim > 1) dx /= lim;
  flight::BladeAngles a = heli_->blade_angles();
  a.main.collective += dx[0];
  a.main.forward += dx[1];
  a.main.right += dx[2];
  a.tail += dx[3];
  heli_->set_blade_angles(a);
  flight::PilotControls c = heli_->controls();
  for (double* v : {&c.collective, &c.longitudinal, &c.lateral, &c.pedal}) *v = std::clamp(*v, 0.0, 100.0);
  heli_->set_controls(c);
  trim_.controls = heli_->controls();
  trim_.angles = heli_->blade_angles();
}

bool ShipApproach::released() const { return cfg_.free_flight && heli_->time() >= cfg_.startup - 0.5 * heli_->time_step(); }

bool ShipApproach::done() const { return !end_reason_.empty() || heli_->time() >= cfg_.duration - 0.5 * heli_->time_step(); }

void ShipApproach::check_contact() {
  if (!cfg_.free_flight || !end_reason_.empty()) return;
  const flight::RigidBodyState& b = heli_->body();
  const double t = heli_->time();
  const wake::ShipPlacement ship = ship_placement(t);
  const double tt = table_time(t);
  for (const Vec3& point : heli_->parameters().landing_gear.contact_points) {
    const Vec3 x = b.position + b.attitude * point;  // mean frame (NED)
    const Vec3 on_body = ship.to_body(x);            // ship frame
    const bool on_ship = ship_.geometry->signed_distance(on_body) <= 0;
    if (!on_ship && x.z() < ship_.geometry->datum().waterline) continue;
    // the point's velocity relative to the surface it touched (the sea is at rest in the mean frame)
    const Vec3 surface = on_ship ? ship_.motion->velocity(on_body, tt) : Vec3::Zero();
    const Vec3 v = b.attitude * (b.velocity + b.rate.cross(point)) - surface;
    std::ostringstream m;
    m.precision(3);
    m << std::fixed << (on_ship ? "touched the ship" : "hit the sea") << " at t = " << t << " s, " << ship_.spot.x() - b.position.x()
      << " m behind the landing spot, sinking at " << v.z() << " m/s and moving at " << Vec3(v.x(), v.y(), 0).norm()
      << " m/s horizontally relative to it";
    end_reason_ = m.str();
    return;
  }
}

void ShipApproach::record() {
  const double t = heli_->time();
  const auto& p = heli_->parameters();
  const auto& o = heli_->outputs();
  ApproachSample& s = sample_;
  s.time = t;
  s.cg = heli_->body().position;
  if (released()) {
    s.distance = ship_.spot.x() - s.cg.x();
    s.speed = (heli_->body().attitude * heli_->body().velocity).x();
  } else {
    s.distance = cfg_.path.distance_at(t);
    s.speed = cfg_.path.speed_at(t);
  }
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
  if (fluid_ && !realtime_) {
    s.wall_cells = fluid_->domain().wall_cells();
    s.voxelisations = fluid_->voxelisations();
    s.face_refreshes = fluid_->face_refreshes();
  } else if (fluid_) {  // in real time the LRM thread owns the domain: as of the last request it served
    const ApproachFluid::Counts n = fluid_->counts();
    s.wall_cells = n.wall_cells;
    s.voxelisations = n.voxelisations;
    s.face_refreshes = n.face_refreshes;
  }
}

}  // namespace ship_lrm::lrm
