// The assembled helicopter: fuselage rigid body, main rotor, tail rotor, airframe aerodynamics,
// engine, and an inflow model behind the rotor interface of thesis 6.5 (Pitt-Peters or the LRM).
// One call of step() is one coupling step (thesis fig. 5.5, flight-model part):
//   1. rotor state and last aerodynamic loads -> inflow model advances over dt -> inflow
//   2. blades advance over dt with that inflow (blade_substeps semi-implicit Euler steps)
//   3. engine / rotor speed advance
//   4. fuselage advances with RK4 (rotor hub loads held over the step; tail rotor, airframe and
//      gravity re-evaluated in every stage), unless the body is held (prescribed motion).
#pragma once

#include <memory>

#include "ship_lrm/flight/airframe.hpp"
#include "ship_lrm/flight/controls.hpp"
#include "ship_lrm/flight/engine.hpp"
#include "ship_lrm/flight/main_rotor.hpp"
#include "ship_lrm/flight/parameters.hpp"
#include "ship_lrm/flight/rigid_body.hpp"
#include "ship_lrm/flight/tail_rotor.hpp"
#include "ship_lrm/rotor/inflow_model.hpp"

namespace ship_lrm::flight {

// Diagnostics of the last step.
struct HelicopterOutputs {
  double time = 0;
  MainRotorLoads rotor;                                                   // mr axes
  TailRotorResult tail;                                                   // body axes
  AirframeLoads airframe;                                                 // body axes
  Wrench rotor_body;                                                      // main-rotor hub loads in body axes about the cg (as applied)
  double main_power = 0, tail_power = 0, engine_power = 0;                // W
  double rotor_speed = 0;                                                 // rad/s
  rotor::RotorInflow inflow;                                              // mr axes
  Vec3 acceleration = Vec3::Zero(), angular_acceleration = Vec3::Zero();  // body axes, du/dt and dp/dt
};

class Helicopter {
 public:
  // inflow: nullptr selects Pitt-Peters.
  explicit Helicopter(HelicopterParameters params, std::unique_ptr<rotor::InflowModel> inflow = nullptr,
                      EngineMode engine_mode = EngineMode::Governed);

  const HelicopterParameters& parameters() const { return p_; }
  void set_controls(const PilotControls& c);  // throws ControlError for out-of-range input (keeps the old controls)
  const PilotControls& controls() const { return controls_; }
  void set_blade_angles(const BladeAngles& a);
  const BladeAngles& blade_angles() const { return angles_; }
  bool right_pedal_increases_tail_pitch() const { return right_pedal_increases_; }

  void set_wind(const Vec3& wind_ned) {
    wind_ = wind_ned;
    other_valid_ = false;
  }
  void set_aerodynamics(bool on) {
    aerodynamics_ = on;
    other_valid_ = false;
  }
  // Hold the fuselage (prescribed motion: trim, whirl tower); rotor, inflow and engine still advance.
  void set_body_held(bool held) { body_held_ = held; }

  // Put the fuselage in `body`, the blades at zero flap and lag, the rotor at its reference speed,
  // and start the inflow model and engine in equilibrium with the resulting loads.
  void reset(const RigidBodyState& body);
  void set_body(const RigidBodyState& body) {
    body_ = body;
    other_valid_ = false;
  }
  void step();

  double time() const { return time_; }
  double time_step() const { return p_.time_step; }
  const RigidBodyState& body() const { return body_; }
  const HelicopterOutputs& outputs() const { return out_; }
  rotor::InflowModel& inflow_model() { return *inflow_; }
  MainRotor& main_rotor() { return rotor_; }
  const MainRotor& main_rotor() const { return rotor_; }
  Engine& engine() { return engine_; }
  EngineState& engine_state() { return engine_state_; }
  const RigidBody& rigid_body() const { return rigid_; }
  // The rotor state handed to the inflow model (mr axes), with the loads of the last step.
  rotor::RotorDiskState disk_state() const;
  // The same without the loads: time, rotor speed, the hub's motion and its pose in the world.
  rotor::RotorDiskState disk_motion() const;
  // Rotation body <- mr.
  const Eigen::Matrix3d& mr_to_body() const { return mr_to_body_; }

 private:
  Wrench other_loads(const RigidBodyState& s, TailRotorResult* tail, AirframeLoads* airframe);
  // Main-rotor hub loads (mr axes, about the hub) as a body wrench about the cg.
  Wrench hub_loads_on_body(const MainRotorLoads& loads, double shaft_torque) const;
  MainRotorInputs rotor_inputs() const;
  Vec3 air_velocity_body(const RigidBodyState& s) const { return s.velocity - s.attitude.conjugate() * wind_; }

  HelicopterParameters p_;
  std::unique_ptr<rotor::InflowModel> inflow_;
  MainRotor rotor_;
  TailRotor tail_;
  Airframe airframe_;
  Engine engine_;
  RigidBody rigid_;
  Eigen::Matrix3d mr_to_body_;
  bool right_pedal_increases_;
  Eigen::Matrix3d inertia_inv_;

  PilotControls controls_;
  BladeAngles angles_;
  Vec3 wind_ = Vec3::Zero();
  bool aerodynamics_ = true, body_held_ = false;

  double time_ = 0;
  RigidBodyState body_;
  EngineState engine_state_;
  double rotor_acceleration_ = 0;
  double shaft_torque_ = 0;
  Wrench other_;              // airframe + tail rotor + gravity at body_ (valid while other_valid_)
  bool other_valid_ = false;  // N m delivered to the main rotor in the last step
  double tail_inflow_ = 0.05;
  HelicopterOutputs out_;
};

}  // namespace ship_lrm::flight
