// Coupled-step speed benchmark (see lrm_benchmark.hpp).
#include "ship_lrm/lrm/lrm_benchmark.hpp"

#include <chrono>
#include <cmath>
#include <sstream>
#include <thread>

#include "ship_lrm/flight/trim.hpp"
#include "ship_lrm/lrm/lrm_inflow.hpp"
#include "ship_lrm/lrm/realtime_inflow.hpp"
#include "ship_lrm/lrm/wall_clock_pacer.hpp"

namespace ship_lrm::lrm {

std::string LrmBenchmarkResult::to_json() const {
  std::ostringstream os;
  os << "{\"benchmark\": \"lrm\", \"backend\": \"" << backend << "\", \"N\": " << nodes << ", \"reach\": " << reach
     << ", \"yaw_rate_deg_s\": " << yaw_rate * 180.0 / M_PI << ", \"cells_per_edge\": " << cells_per_edge << ", \"cells\": " << cells
     << ", \"flight_steps\": " << flight_steps << ", \"lbm_steps\": " << lbm_steps << ", \"simulated_s\": " << simulated_seconds
     << ", \"wall_s\": " << wall_seconds << ", \"clock_over_sim\": " << clock_over_sim << ", \"mlups\": " << mlups;
  if (!faces.empty()) os << ", \"faces\": \"" << faces << "\"";
  if (far_field_builds > 0) os << ", \"far_field_builds\": " << far_field_builds << ", \"far_field_s\": " << far_field_s;
  if (parts_clock_over_sim > 0) os << ", \"clock_over_sim_parts_timed\": " << parts_clock_over_sim;
  if (has_split)
    os << ", \"split_s\": {\"lbm\": " << lbm_s << ", \"motion\": " << motion_s << ", \"forces\": " << forces_s
       << ", \"inflow\": " << inflow_s << ", \"flight\": " << flight_s << "}";
  if (realtime)
    os << ", \"realtime\": true, \"pipelined\": " << (pipelined ? "true" : "false") << ", \"deadline_misses\": " << deadline_misses
       << ", \"miss_fraction\": " << miss_fraction << ", \"worst_wait_s\": " << worst_wait_s << ", \"worst_step_s\": " << worst_step_s;
  os << "}";
  return os.str();
}

namespace {

// The benchmarks' set-up: the Bo 105 trimmed with Pitt-Peters at `speed`, then flown (fuselage held at
// the trim, turning at yaw_rate) with the inflow model `make_inflow(cfg)` builds; reset() runs the LRM
// warm-up (not timed).
template <typename Inflow, typename Make>
std::pair<std::unique_ptr<flight::Helicopter>, Inflow*> trimmed_helicopter(const flight::HelicopterParameters& p, LrmConfig cfg,
                                                                           double seconds, double speed, double yaw_rate,
                                                                           Make make_inflow) {
  if (!(seconds > 0)) throw ConfigError("lrm benchmark: needs seconds > 0");
  if (!std::isfinite(yaw_rate)) throw ConfigError("lrm benchmark: the yaw rate is not finite");
  cfg.radius = p.main_rotor.radius;
  cfg.density = p.density;
  flight::Helicopter pp(p);
  flight::TrimTarget t;
  t.speed = speed;
  const flight::TrimResult trim = flight::trim(pp, t);
  if (!trim.converged) throw std::runtime_error(trim.message);
  std::unique_ptr<Inflow> inflow = make_inflow(cfg);
  Inflow* raw = inflow.get();
  auto heli = std::make_unique<flight::Helicopter>(p, std::move(inflow), flight::EngineMode::ConstantSpeed);
  heli->set_controls(trim.controls);
  heli->set_body_held(true);
  flight::RigidBodyState body = trim.body;
  body.rate.z() = yaw_rate;  // body z (FRD): positive is a turn to starboard
  heli->reset(body);
  return {std::move(heli), raw};
}

}  // namespace

LrmBenchmarkResult run_lrm_benchmark(const flight::HelicopterParameters& p, const LrmConfig& cfg_in, double seconds, double speed,
                                     double warm_up, double yaw_rate) {
  auto [heli_ptr, lrm] = trimmed_helicopter<LrmInflow>(p, cfg_in, seconds, speed, yaw_rate,
                                                       [&](const LrmConfig& c) { return std::make_unique<LrmInflow>(c, warm_up); });
  flight::Helicopter& heli = *heli_ptr;
  const LrmConfig& cfg = cfg_in;
  LrmBenchmarkResult r;
  r.backend = lrm->domain().solver().backend_name();
  r.nodes = cfg.nodes;
  r.reach = cfg.reach;
  r.yaw_rate = yaw_rate;
  r.cells_per_edge = lrm->domain().cells_per_edge();
  r.cells = static_cast<long>(lrm->domain().solver().lattice().cells());
  const long steps = static_cast<long>(std::ceil(seconds / heli.time_step()));
  // `steps` coupled steps; the wall time and the parts' times (LrmInflow::times) they took
  const auto timed = [&](bool time_parts, CouplingTimes& parts) {
    lrm->set_time_parts(time_parts);
    const CouplingTimes before = lrm->times();
    const auto t0 = std::chrono::steady_clock::now();
    for (long i = 0; i < steps; ++i) heli.step();
    lrm->domain().solver().synchronize();
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const CouplingTimes& after = lrm->times();
    parts.motion = after.motion - before.motion;
    parts.forces = after.forces - before.forces;
    parts.lbm = after.lbm - before.lbm;
    parts.inflow = after.inflow - before.inflow;
    lrm->set_time_parts(false);
    return wall;
  };
  // t_clock / t_sim as the coupled runs step (no wait between the LBM steps and the inflow's
  // read-back); on a device backend the parts come from a second run that waits there to tell them
  // apart (the CPU's steps are done when step() returns: one run gives both)
  const long lbm0 = lrm->lbm_steps();
  CouplingTimes parts;
  r.wall_seconds = timed(false, parts);
  r.lbm_steps = lrm->lbm_steps() - lbm0;
  double parts_wall = r.wall_seconds;
  if (r.backend != "cpu") {
    parts_wall = timed(true, parts);
    r.parts_clock_over_sim = parts_wall / (steps * heli.time_step());
  }
  r.has_split = true;
  r.motion_s = parts.motion;
  r.forces_s = parts.forces;
  r.lbm_s = parts.lbm;
  r.inflow_s = parts.inflow;
  r.flight_s = parts_wall - r.motion_s - r.forces_s - r.lbm_s - r.inflow_s;
  r.far_field_builds = static_cast<long>(lrm->domain().far_field_builds());
  r.far_field_s = lrm->domain().far_field_seconds();
  r.flight_steps = steps;
  r.simulated_seconds = steps * heli.time_step();
  r.clock_over_sim = r.wall_seconds / r.simulated_seconds;
  r.mlups = static_cast<double>(r.cells) * r.lbm_steps / r.wall_seconds / 1e6;
  return r;
}

LrmBenchmarkResult run_realtime_benchmark(const flight::HelicopterParameters& p, const LrmConfig& cfg_in, double seconds, double speed,
                                          double warm_up, RealTimeMode mode, double yaw_rate) {
  auto [heli_ptr, rt] = trimmed_helicopter<RealTimeInflow>(p, cfg_in, seconds, speed, yaw_rate,
                                                           [&](const LrmConfig& c) { return make_realtime_lrm(c, warm_up, 1.0, mode); });
  LrmInflow& lrm = static_cast<LrmInflow&>(rt->slow());
  flight::Helicopter& heli = *heli_ptr;
  const LrmConfig& cfg = cfg_in;
  LrmBenchmarkResult r;
  r.realtime = true;
  r.pipelined = mode == RealTimeMode::Pipelined;
  r.backend = lrm.domain().solver().backend_name();
  r.nodes = cfg.nodes;
  r.reach = cfg.reach;
  r.yaw_rate = yaw_rate;
  r.cells_per_edge = lrm.domain().cells_per_edge();
  r.cells = static_cast<long>(lrm.domain().solver().lattice().cells());
  const long lbm0 = lrm.lbm_steps();
  const long steps = static_cast<long>(std::ceil(seconds / heli.time_step()));
  using clock = std::chrono::steady_clock;
  WallClockPacer pacer;
  for (long i = 0; i < steps; ++i) {
    const double t = (i + 1) * heli.time_step();
    rt->set_deadline(pacer.due(t));
    const auto s0 = clock::now();
    heli.step();
    r.worst_step_s = std::max(r.worst_step_s, std::chrono::duration<double>(clock::now() - s0).count());
    pacer.wait_until(t);  // paced: the next step starts on time (or at once when late)
  }
  r.wall_seconds = pacer.elapsed();
  const RealTimeStats st = rt->stats();
  r.flight_steps = steps;
  r.simulated_seconds = steps * heli.time_step();
  r.clock_over_sim = r.wall_seconds / r.simulated_seconds;
  r.deadline_misses = st.deadline_misses;
  r.miss_fraction = st.miss_fraction();
  r.worst_wait_s = st.worst_wait_s;
  rt->reset(heli.disk_state());  // waits for the LRM thread, so its step count is final
  r.lbm_steps = lrm.lbm_steps() - lbm0;
  r.mlups = static_cast<double>(r.cells) * r.lbm_steps / r.wall_seconds / 1e6;
  return r;
}

}  // namespace ship_lrm::lrm
