// Pilot controls in % of travel and their mapping to blade pitch (ranges in config/bo105.yaml,
// section controls). Collective 0..100 %; longitudinal cyclic, lateral cyclic and pedals 0..100 %
// with 50 % at the centre; 100 % longitudinal is full forward, 100 % lateral full right, 100 % pedal
// full right (nose right).
#pragma once

#include <stdexcept>

#include "ship_lrm/flight/main_rotor.hpp"
#include "ship_lrm/flight/parameters.hpp"

namespace ship_lrm::flight {

struct PilotControls {
  double collective = 50, longitudinal = 50, lateral = 50, pedal = 50;  // %
};

struct BladeAngles {
  BladePitch main;
  double tail = 0;  // rad, tail-rotor collective pitch
};

// Out-of-range or non-finite controls: what() names the control.
class ControlError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// right_pedal_increases_tail_pitch: true when more tail-rotor pitch yaws the nose right.
BladeAngles map_controls(const PilotControls& c, const ControlParameters& p, bool right_pedal_increases_tail_pitch);
// Inverse of map_controls (for trim output).
PilotControls unmap_controls(const BladeAngles& a, const ControlParameters& p, bool right_pedal_increases_tail_pitch);

}  // namespace ship_lrm::flight
