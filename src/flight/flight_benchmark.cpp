// Flight-model speed benchmark (see flight_benchmark.hpp).
#include "ship_lrm/flight/flight_benchmark.hpp"

#include <chrono>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "ship_lrm/flight/trim.hpp"

namespace ship_lrm::flight {

std::string FlightBenchmarkResult::to_json() const {
  std::ostringstream os;
  os << "{\"benchmark\": \"flight\", \"model\": \"bo105 blade element + pitt_peters\", \"threads\": 1, \"speed_m_s\": " << speed
     << ", \"time_step_s\": " << time_step << ", \"steps\": " << steps << ", \"simulated_s\": " << simulated_seconds
     << ", \"wall_s\": " << wall_seconds << ", \"us_per_step\": " << microseconds_per_step << ", \"real_time_factor\": " << real_time_factor
     << "}";
  return os.str();
}

FlightBenchmarkResult run_flight_benchmark(const HelicopterParameters& p, double seconds, double speed) {
  if (!(seconds > 0)) throw std::invalid_argument("benchmark duration must be > 0 s");
  Helicopter heli(p, nullptr, EngineMode::Governed);
  TrimTarget target;
  target.speed = speed;
  const TrimResult t = trim(heli, target);
  if (!t.converged) throw std::runtime_error(t.message);
  const RigidBodyState body = heli.body();
  const auto blades = heli.main_rotor().blades();
  const EngineState engine = heli.engine_state();
  FlightBenchmarkResult r;
  r.time_step = p.time_step;
  r.speed = speed;
  const long segment = static_cast<long>(std::ceil(2.0 / p.time_step));
  const long total = static_cast<long>(std::ceil(seconds / p.time_step));
  const auto t0 = std::chrono::steady_clock::now();
  while (r.steps < total) {
    heli.set_body(body);
    heli.main_rotor().blades() = blades;
    heli.engine_state() = engine;
    for (long i = 0; i < segment && r.steps < total; ++i, ++r.steps) heli.step();
  }
  r.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.simulated_seconds = r.steps * p.time_step;
  r.microseconds_per_step = 1e6 * r.wall_seconds / r.steps;
  r.real_time_factor = r.simulated_seconds / r.wall_seconds;
  return r;
}

}  // namespace ship_lrm::flight
