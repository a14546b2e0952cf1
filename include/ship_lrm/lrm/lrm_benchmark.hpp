// Speed of the coupled step (flight model + LRM domain): wall-clock time per simulated second.
#pragma once

#include <string>

#include "ship_lrm/flight/parameters.hpp"
#include "ship_lrm/lrm/domain.hpp"

namespace ship_lrm::lrm {

struct LrmBenchmarkResult {
  std::string backend;
  int nodes = 0, cells_per_edge = 0;
  double reach = 0;
  long cells = 0, flight_steps = 0, lbm_steps = 0;
  double simulated_seconds = 0, wall_seconds = 0;
  double clock_over_sim = 0;  // t_clock / t_sim (thesis 8.3.1; < 1 is real time)
  double mlups = 0;           // million lattice updates per second
  std::string to_json() const;
};

// Trims the Bo 105 with Pitt-Peters at `speed`, then runs the coupled step (LRM inflow, fuselage
// held at the trim) for `seconds` of simulated time after `warm_up` seconds that are not timed.
LrmBenchmarkResult run_lrm_benchmark(const flight::HelicopterParameters& p, const LrmConfig& cfg, double seconds, double speed,
                                     double warm_up);

}  // namespace ship_lrm::lrm
