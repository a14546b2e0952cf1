// Engine, governor and rotor-speed dynamics (see engine.hpp).
#include "ship_lrm/flight/engine.hpp"

#include <algorithm>

namespace ship_lrm::flight {

Engine::Engine(const HelicopterParameters& p, EngineMode mode)
    : mode_(mode),
      omega_ref_(p.main_rotor.rotor_speed),
      inertia_(p.main_rotor.rotor_inertia),
      max_power_(p.engine.max_power),
      tau_(p.engine.time_constant),
      kp_(p.engine.governor_gain),
      ki_(p.engine.governor_integral),
      anticipation_(p.engine.load_anticipation) {}

void Engine::trim(EngineState& s, double main_torque, double tail_power) const {
  s.rotor_speed = omega_ref_;
  s.power = main_torque * omega_ref_ + tail_power;
  s.governor_integral = 0;
  s.trim_power = s.power;
}

double Engine::advance(EngineState& s, double main_torque, double tail_power, double dt) const {
  const double load = main_torque * s.rotor_speed + tail_power;
  if (mode_ == EngineMode::ConstantSpeed) {
    s.power = load;
    s.rotor_speed = omega_ref_;
    return 0;
  }
  const double err = omega_ref_ - s.rotor_speed;
  s.governor_integral += err * dt;
  // the governor's datum: the trimmed power, plus the anticipated share of the load change
  const double datum = s.trim_power + anticipation_ * (load - s.trim_power);
  const double command = std::clamp(datum + inertia_ * s.rotor_speed * (kp_ * err + ki_ * s.governor_integral), 0.0, max_power_);
  // anti-windup: stop integrating while the command sits on a limit
  if (command == max_power_ || command == 0.0) s.governor_integral -= err * dt;
  s.power += dt / tau_ * (command - s.power);
  const double acc = ((s.power - tail_power) / std::max(s.rotor_speed, 1e-3) - main_torque) / inertia_;
  s.rotor_speed += dt * acc;
  return acc;
}

}  // namespace ship_lrm::flight
