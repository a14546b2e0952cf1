// The quick LRM set-up of the CI tests: N = 32, a = 1.25 (thesis 6.4 domain at half resolution), CPU.
#pragma once

#include <cmath>

#include "ship_lrm/lrm/domain.hpp"
#include "ship_lrm/rotor/inflow_model.hpp"

namespace ship_lrm::lrm::test {

inline LrmConfig quick_config(int nodes = 32, double reach = 1.25) {
  LrmConfig c;
  c.nodes = nodes;
  c.reach = reach;
  c.backend = lbm::Backend::Cpu;
  return c;
}

// A Bo 105-like rotor state at coupling step k: forward flight near 20 m/s with slowly varying
// hub velocity and thrust (the inflow-model tests' input).
inline rotor::RotorDiskState disk_state_at(int k, double dt) {
  rotor::RotorDiskState s;
  s.time = k * dt;
  s.radius = 4.92;
  s.rotor_speed = 44.4;
  s.density = 1.1934;
  s.hub_velocity = ship_lrm::Vec3(20.0 + 0.5 * std::sin(0.1 * k), 0.0, 0.5);
  s.aero_force = ship_lrm::Vec3(0, 0, -24525.0 - 2000.0 * std::sin(0.05 * k));
  s.harmonics.cos[0] = s.aero_force;
  return s;
}

}  // namespace ship_lrm::lrm::test
