// The assembled helicopter and its coupling step (see helicopter.hpp).
#include "ship_lrm/flight/helicopter.hpp"

#include <cmath>

#include "ship_lrm/rotor/pitt_peters.hpp"

namespace ship_lrm::flight {
namespace {

Eigen::Matrix3d skew(const Vec3& v) {
  Eigen::Matrix3d m;
  m << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return m;
}

Eigen::Matrix3d inertia_matrix(const MassParameters& m) {
  Eigen::Matrix3d i;
  i << m.ixx, 0, -m.ixz, 0, m.iyy, 0, -m.ixz, 0, m.izz;
  return i;
}

// Columns: the mr axes in body axes; the shaft tilts forward by gamma_s (thrust leans forward).
Eigen::Matrix3d mr_rotation(double tilt) {
  Eigen::Matrix3d r;
  r << std::cos(tilt), 0, -std::sin(tilt), 0, 1, 0, std::sin(tilt), 0, std::cos(tilt);
  return r;
}

}  // namespace

Helicopter::Helicopter(HelicopterParameters params, std::unique_ptr<rotor::InflowModel> inflow, EngineMode engine_mode)
    : p_(std::move(params)),
      inflow_(inflow ? std::move(inflow) : std::make_unique<rotor::PittPetersInflow>()),
      rotor_(p_),
      // The tail rotor pushes the tail against the main rotor's torque reaction: to port for a
      // clockwise rotor (reaction yaws the nose left), to starboard for a counterclockwise one.
      tail_(p_.tail_rotor, p_.main_rotor.clockwise ? Vec3(0, -1, 0) : Vec3(0, 1, 0)),
      airframe_(p_),
      engine_(p_, engine_mode),
      rigid_(p_.mass.mass, inertia_matrix(p_.mass)),
      mr_to_body_(mr_rotation(p_.main_rotor.shaft_tilt)),
      right_pedal_increases_(p_.main_rotor.clockwise),
      inertia_inv_(inertia_matrix(p_.mass).inverse()) {
  angles_ = map_controls(controls_, p_.controls, right_pedal_increases_);
  engine_state_.rotor_speed = engine_.reference_speed();
}

void Helicopter::set_controls(const PilotControls& c) {
  angles_ = map_controls(c, p_.controls, right_pedal_increases_);
  controls_ = c;
  other_valid_ = false;
}

void Helicopter::set_blade_angles(const BladeAngles& a) {
  angles_ = a;
  controls_ = unmap_controls(a, p_.controls, right_pedal_increases_);
  other_valid_ = false;
}

rotor::RotorDiskState Helicopter::disk_motion() const {
  rotor::RotorDiskState d;
  d.time = time_;
  d.radius = p_.main_rotor.radius;
  d.rotor_speed = engine_state_.rotor_speed;
  d.density = p_.density;
  const Vec3 hub_body = air_velocity_body(body_) + body_.rate.cross(p_.main_rotor.hub_position);
  d.hub_velocity = mr_to_body_.transpose() * hub_body;
  d.body_rate = mr_to_body_.transpose() * body_.rate;
  const Eigen::Matrix3d body_to_world = body_.attitude.toRotationMatrix();
  d.hub_position = body_.position + body_to_world * p_.main_rotor.hub_position;
  d.mr_to_world = body_to_world * mr_to_body_;
  d.hub_world_velocity = body_to_world * (body_.velocity + body_.rate.cross(p_.main_rotor.hub_position));
  return d;
}

rotor::RotorDiskState Helicopter::disk_state() const {
  rotor::RotorDiskState d = disk_motion();
  d.aero_force = out_.rotor.aero_force;
  d.aero_moment = out_.rotor.aero_moment;
  if (inflow_->needs_harmonics()) d.harmonics = rotor_.force_record().harmonics();
  return d;
}

MainRotorInputs Helicopter::rotor_inputs() const {
  MainRotorInputs in;
  in.pitch = angles_.main;
  in.inflow = out_.inflow;
  const Eigen::Matrix3d b2m = mr_to_body_.transpose();
  in.body_rate = b2m * body_.rate;
  // A held (prescribed) body does not accelerate, whatever its loads are.
  const Vec3 acc = body_held_ ? Vec3::Zero() : out_.acceleration;
  const Vec3 ang_acc = body_held_ ? Vec3::Zero() : out_.angular_acceleration;
  in.body_angular_acceleration = b2m * ang_acc;
  const Vec3& r = p_.main_rotor.hub_position;
  const Vec3 a_hub = acc + body_.rate.cross(body_.velocity) + ang_acc.cross(r) + body_.rate.cross(body_.rate.cross(r));
  const Vec3 g_body = body_.attitude.conjugate() * Vec3(0, 0, p_.mass.gravity);
  in.hub_specific_force = b2m * (a_hub - g_body);
  in.rotor_speed = engine_state_.rotor_speed;
  in.rotor_acceleration = rotor_acceleration_;
  in.density = p_.density;
  in.speed_of_sound = p_.speed_of_sound;
  in.aerodynamics = aerodynamics_;
  return in;
}

Wrench Helicopter::hub_loads_on_body(const MainRotorLoads& loads, double shaft_torque) const {
  // about the shaft the fuselage feels the drive torque's reaction, not the blades' aerodynamic torque
  Vec3 m_mr = loads.moment;
  m_mr.z() = (p_.main_rotor.clockwise ? -1.0 : 1.0) * shaft_torque;
  Wrench w;
  w.force = mr_to_body_ * loads.force;
  w.moment = mr_to_body_ * m_mr + p_.main_rotor.hub_position.cross(w.force);
  return w;
}

Wrench Helicopter::other_loads(const RigidBodyState& s, TailRotorResult* tail, AirframeLoads* airframe) {
  Wrench w;
  w.force = s.attitude.conjugate() * Vec3(0, 0, p_.mass.mass * p_.mass.gravity);
  if (!aerodynamics_) return w;
  const Vec3 air = air_velocity_body(s);
  const Vec3 tail_air = -(air + s.rate.cross(p_.tail_rotor.position));
  const TailRotorResult t = tail_.evaluate(angles_.tail, engine_state_.rotor_speed, tail_air, p_.density, &tail_inflow_);
  w += t.loads;
  // main-rotor wake at the airframe: wake_factor x mean induced velocity, fading with wake skew
  const Vec3 hub_air_mr = mr_to_body_.transpose() * (air + s.rate.cross(p_.main_rotor.hub_position));
  const double v0 = out_.inflow.mean.z() + hub_air_mr.z();
  const double through = v0 - hub_air_mr.z();
  const double inplane = std::hypot(hub_air_mr.x(), hub_air_mr.y());
  const double fade = through > 0 ? through / std::hypot(through, inplane) : 0.0;  // cos(chi)
  AirframeInputs ai;
  ai.air_velocity = air;
  ai.rate = s.rate;
  ai.density = p_.density;
  ai.rotor_downwash = mr_to_body_ * Vec3(0, 0, p_.fuselage.wake_factor * std::max(v0, 0.0) * fade);
  const AirframeLoads a = airframe_.evaluate(ai);
  w += a.total();
  if (tail) *tail = t;
  if (airframe) *airframe = a;
  return w;
}

void Helicopter::reset(const RigidBodyState& body) {
  body_ = body;
  other_valid_ = false;
  time_ = 0;
  for (auto& b : rotor_.blades()) b = BladeState{};
  rotor_.set_azimuth(0);
  engine_state_.rotor_speed = engine_.reference_speed();
  rotor_acceleration_ = 0;
  out_ = HelicopterOutputs{};
  // A first evaluation with a momentum-theory inflow guess, then the steady inflow for those loads,
  // and the accelerations that belong to them (so the blades feel the right hub motion from the first
  // step: with the aerodynamics off the free fall is exact from t = 0).
  rotor::RotorDiskState d = disk_state();
  out_.inflow.mean = -d.hub_velocity + Vec3(0, 0, 0.05 * d.rotor_speed * d.radius);
  TailRotorResult t;
  for (int pass = 0; pass < 12; ++pass) {
    out_.rotor = rotor_.evaluate(rotor_inputs());
    d = disk_state();
    inflow_->reset(d);
    out_.inflow = inflow_->inflow();
    out_.rotor_body = hub_loads_on_body(out_.rotor, out_.rotor.aero_torque);
    Wrench w = other_loads(body_, &t, &out_.airframe);
    w += out_.rotor_body;
    const RigidBodyDerivative start = rigid_.derivative(body_, w);
    out_.acceleration = start.acceleration;
    out_.angular_acceleration = start.angular_acceleration;
  }
  out_.tail = t;
  // seed the azimuth record with the current blade forces
  std::vector<Vec3> forces(p_.main_rotor.blades, out_.rotor.aero_force / p_.main_rotor.blades);
  rotor_.force_record().fill(forces);
  engine_.trim(engine_state_, out_.rotor.aero_torque, t.power);
  out_.rotor_speed = engine_state_.rotor_speed;
  shaft_torque_ = out_.rotor.aero_torque;
}

void Helicopter::step() {
  const double dt = p_.time_step;
  // 1. inflow
  const rotor::RotorDiskState disk = disk_state();
  inflow_->advance(disk, dt);
  out_.inflow = inflow_->inflow();
  // 2. blades
  // The blades and the fuselage share one algebraic loop (hub acceleration <-> blade inertial loads):
  // solve it every blade sub-step with the fuselage's equations (main_rotor.hpp).
  const Eigen::Matrix3d& r_mb = mr_to_body_;
  const Vec3& rh = p_.main_rotor.hub_position;
  const Vec3 g_body = body_.attitude.conjugate() * Vec3(0, 0, p_.mass.gravity);
  // airframe, tail rotor and gravity at the current state (computed at the end of the last step)
  const Wrench other = other_valid_ ? other_ : other_loads(body_, nullptr, nullptr);
  const double shaft_sign = p_.main_rotor.clockwise ? -1.0 : 1.0;
  const RotorCoupling couple = [&](const Vec6& w0, const Mat6& k) -> Vec6 {
    Vec6 x;
    if (body_held_) {
      x.head<3>() = -(r_mb.transpose() * g_body);
      x.tail<3>().setZero();
      return x;
    }
    Vec6 w0m = w0;
    Mat6 km = k;
    w0m[5] = shaft_sign * shaft_torque_;  // about the shaft the fuselage feels the drive torque
    km.row(5).setZero();
    Mat6 j = Mat6::Zero();  // mr wrench about the hub -> body wrench about the cg
    j.block<3, 3>(0, 0) = r_mb;
    j.block<3, 3>(3, 3) = r_mb;
    j.block<3, 3>(3, 0) = skew(rh) * r_mb;
    Mat6 l = Mat6::Zero();  // body wrench -> (hub specific force, angular acceleration) in mr axes
    l.block<3, 3>(0, 0) = r_mb.transpose() / rigid_.mass();
    l.block<3, 3>(0, 3) = -r_mb.transpose() * skew(rh) * inertia_inv_;
    l.block<3, 3>(3, 3) = r_mb.transpose() * inertia_inv_;
    const Vec3 gyro = -body_.rate.cross(rigid_.inertia() * body_.rate);
    Vec6 l0;
    l0.head<3>() = r_mb.transpose() * (-g_body - skew(rh) * inertia_inv_ * gyro + body_.rate.cross(body_.rate.cross(rh)));
    l0.tail<3>() = r_mb.transpose() * inertia_inv_ * gyro;
    Vec6 wb0;
    wb0 << other.force, other.moment;
    wb0 += j * w0m;
    const Mat6 a = Mat6::Identity() - l * j * km;
    return a.partialPivLu().solve(l * wb0 + l0);
  };
  MainRotorLoads loads = rotor_.step(rotor_inputs(), dt, p_.blade_substeps, &couple);
  out_.rotor = loads;
  // 3. engine and rotor speed
  const double tail_power = aerodynamics_ ? out_.tail.power : 0.0;
  rotor_acceleration_ = engine_.advance(engine_state_, loads.aero_torque, tail_power, dt);
  out_.main_power = loads.aero_torque * engine_state_.rotor_speed;
  out_.tail_power = tail_power;
  out_.engine_power = engine_state_.power;
  out_.rotor_speed = engine_state_.rotor_speed;
  // Hub loads on the fuselage; about the shaft the fuselage feels the drive torque's reaction.
  const double shaft_torque = engine_.mode() == EngineMode::ConstantSpeed
                                  ? loads.aero_torque
                                  : (engine_state_.power - tail_power) / std::max(engine_state_.rotor_speed, 1e-3);
  shaft_torque_ = shaft_torque;
  const Wrench rotor_body = hub_loads_on_body(loads, shaft_torque);
  out_.rotor_body = rotor_body;
  // 4. fuselage
  const auto total = [&](const RigidBodyState& s) {
    Wrench w = other_loads(s, nullptr, nullptr);
    w += rotor_body;
    return w;
  };
  if (!body_held_) body_ = rigid_.step(body_, dt, total);
  time_ += dt;
  TailRotorResult t;
  other_ = other_loads(body_, &t, &out_.airframe);
  other_valid_ = true;
  Wrench w = other_;
  out_.tail = t;
  w += rotor_body;
  const RigidBodyDerivative d = rigid_.derivative(body_, w);
  out_.acceleration = d.acceleration;
  out_.angular_acceleration = d.angular_acceleration;
  out_.time = time_;
  if (!body_.velocity.allFinite() || !body_.rate.allFinite() || !body_.position.allFinite())
    throw std::runtime_error("flight model diverged at t = " + std::to_string(time_) + " s (non-finite fuselage state)");
}

}  // namespace ship_lrm::flight
