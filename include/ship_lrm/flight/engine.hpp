// Engine and rotor speed. Two modes:
//  * constant rotor speed: the engine always supplies the power needed (the thesis' flight model);
//  * governed: a first-order engine (time constant tau) with a power limit, commanded by a
//    proportional-integral rotor-speed governor (optionally with a share of the load fed forward,
//    "load anticipation"); the rotor and drive train
//    (polar inertia I_R) integrate  I_R dOmega/dt = (P_engine - P_tail) / Omega - Q_main,
//    so the rotor speed droops when the demand outruns the engine or its limit (flight tests in the
//    thesis 8.2.2 showed 5 +- 1 %).
#pragma once

#include "ship_lrm/flight/parameters.hpp"

namespace ship_lrm::flight {

enum class EngineMode { ConstantSpeed, Governed };

struct EngineState {
  double rotor_speed = 0;  // rad/s
  double power = 0;        // W delivered by the engine
  double governor_integral = 0;
  double trim_power = 0;  // W, the power at the last trim (the governor's datum)
};

class Engine {
 public:
  Engine(const HelicopterParameters& p, EngineMode mode);
  EngineMode mode() const { return mode_; }
  void set_mode(EngineMode m) { mode_ = m; }
  double reference_speed() const { return omega_ref_; }

  // Start in equilibrium with this load.
  void trim(EngineState& s, double main_torque, double tail_power) const;
  // Advance over dt; returns the rotor acceleration used. main_torque: aerodynamic torque of the main
  // rotor (N m); tail_power: W taken by the tail rotor.
  double advance(EngineState& s, double main_torque, double tail_power, double dt) const;

 private:
  EngineMode mode_;
  double omega_ref_, inertia_, max_power_, tau_, kp_, ki_, anticipation_;
};

}  // namespace ship_lrm::flight
