// Speed of the coupled step (flight model + LRM domain): wall-clock time per simulated second.
#pragma once

#include <string>

#include "ship_lrm/flight/parameters.hpp"
#include "ship_lrm/lrm/domain.hpp"
#include "ship_lrm/lrm/realtime_inflow.hpp"

namespace ship_lrm::lrm {

struct LrmBenchmarkResult {
  std::string backend;
  int nodes = 0, cells_per_edge = 0;
  double reach = 0, yaw_rate = 0;  // yaw_rate: rad/s of the held fuselage (a steady turn; 0: straight)
  long cells = 0, flight_steps = 0, lbm_steps = 0;
  double simulated_seconds = 0, wall_seconds = 0;
  double clock_over_sim = 0;  // t_clock / t_sim (thesis 8.3.1; < 1 is real time)
  double mlups = 0;           // million lattice updates per second
  // simulated-time run: where the wall time went (LrmInflow::times(); flight = the rest). On a device
  // backend from a second run of as many steps that waits for the device after the LBM steps, whose
  // t_clock / t_sim is parts_clock_over_sim (0: not run, the CPU's split is the timed run's own)
  bool has_split = false;
  double motion_s = 0, forces_s = 0, lbm_s = 0, inflow_s = 0, flight_s = 0;
  double parts_clock_over_sim = 0;
  // LrmConfig::rotor_far_field: how often its shape was computed in the whole run (warm-up included), and
  // the time that took
  long far_field_builds = 0;
  double far_field_s = 0;
  std::string faces;  // the caller's name of the face set-up (written to the JSON when not empty)
  // paced wall-clock run (run_realtime_benchmark): firm deadlines, Pitt-Peters fallback
  bool realtime = false;
  bool pipelined = false;
  long deadline_misses = 0;
  double miss_fraction = 0, worst_wait_s = 0, worst_step_s = 0;
  std::string to_json() const;
};

// Trims the Bo 105 with Pitt-Peters at `speed`, then runs the coupled step (LRM inflow, fuselage
// held at the trim) for `seconds` of simulated time after `warm_up` seconds that are not timed.
// yaw_rate (rad/s): the held fuselage turns at this rate (its trim is still the straight one), so
// that the LRM domain rotates and each LBM step includes the fictitious forces of its frame (the
// step of a manoeuvre; 0: the inertial step of straight flight).
LrmBenchmarkResult run_lrm_benchmark(const flight::HelicopterParameters& p, const LrmConfig& cfg, double seconds, double speed,
                                     double warm_up, double yaw_rate = 0.0);

// The same coupled step paced to the wall clock (RealTimeInflow): each flight-model step is due at
// t0 + k dt; the LRM inflow that misses that deadline is replaced by Pitt-Peters and counted.
LrmBenchmarkResult run_realtime_benchmark(const flight::HelicopterParameters& p, const LrmConfig& cfg, double seconds, double speed,
                                          double warm_up, RealTimeMode mode = RealTimeMode::LockStep, double yaw_rate = 0.0);

}  // namespace ship_lrm::lrm
