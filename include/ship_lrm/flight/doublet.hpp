// Doublet manoeuvre from trimmed flight (thesis 8.2.2, fig. 8.8 and appendix VI): one control is
// moved +amplitude for `pulse` seconds, then -amplitude for `pulse` seconds, then back to trim,
// while the other controls stay at their trim values.
#pragma once

#include <string>
#include <vector>

#include "ship_lrm/flight/trim.hpp"

namespace ship_lrm::flight {

enum class ControlAxis { Collective, Longitudinal, Lateral, Pedal };
ControlAxis parse_control_axis(const std::string& name);  // throws std::invalid_argument
std::string to_string(ControlAxis a);

struct DoubletOptions {
  ControlAxis axis = ControlAxis::Lateral;
  double speed = 13.37;           // m/s (the lateral doublet of thesis fig. 8.8)
  double amplitude = 10.0;        // % of travel
  double start = 1.0;             // s after the trim
  double pulse = 1.0;             // s, length of each half
  double duration = 8.0;          // s
  double sample_interval = 0.01;  // s
  EngineMode engine = EngineMode::Governed;
};

struct DoubletSample {
  double time;
  PilotControls controls;
  Vec3 rates;                       // p, q, r, rad/s
  Vec3 attitude;                    // roll, pitch, yaw, rad
  double rate_of_descent;           // m/s, positive down
  double rotor_speed_ratio;         // Omega / Omega_ref
  double main_power, engine_power;  // W
};

struct DoubletResult {
  TrimResult trim;
  std::vector<DoubletSample> samples;
};

// Trims at opt.speed, then flies the doublet. Throws std::runtime_error when the trim fails.
DoubletResult run_doublet(const HelicopterParameters& params, const DoubletOptions& opt);

}  // namespace ship_lrm::flight
