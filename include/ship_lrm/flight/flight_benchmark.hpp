// Speed of the flight model at the coupling step: wall-clock time per simulated second, single thread.
#pragma once

#include <string>

#include "ship_lrm/flight/parameters.hpp"

namespace ship_lrm::flight {

struct FlightBenchmarkResult {
  double simulated_seconds = 0, wall_seconds = 0;
  long steps = 0;
  double time_step = 0;
  double microseconds_per_step = 0;
  double real_time_factor = 0;  // simulated / wall
  double speed = 0;             // m/s of the trimmed flight it runs from
  std::string to_json() const;
};

// Trims at `speed`, then times free flight (Pitt-Peters inflow, governed engine) in segments of
// 2 s restarted from the trim until `seconds` of simulated time are done.
FlightBenchmarkResult run_flight_benchmark(const HelicopterParameters& p, double seconds, double speed);

}  // namespace ship_lrm::flight
