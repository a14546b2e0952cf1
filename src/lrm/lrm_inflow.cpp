// The LRM domain behind the rotor-inflow interface (see lrm_inflow.hpp).
#include "ship_lrm/lrm/lrm_inflow.hpp"

#include <chrono>
#include <cmath>

namespace ship_lrm::lrm {
namespace {
using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point& t) {  // and restarts t
  const auto now = Clock::now();
  const double s = std::chrono::duration<double>(now - t).count();
  t = now;
  return s;
}
}  // namespace

LrmInflow::LrmInflow(const LrmConfig& cfg, double warm_up) : domain_(cfg), warm_up_(warm_up) {}

void LrmInflow::take(const rotor::RotorDiskState& s, CouplingTimes* times) {
  auto t = Clock::now();
  LrmDomain::Motion m;
  m.air_velocity = -s.hub_velocity;
  m.omega = s.body_rate;
  const double dt = s.time - previous_time_;
  if (have_previous_ && dt > 0) {
    // d/dt in the inertial frame of a vector given in rotating axes: dV/dt|mr + omega x V
    m.omega_dot = (s.body_rate - previous_rate_) / dt;
    m.hub_acceleration = (s.hub_velocity - previous_velocity_) / dt + s.body_rate.cross(s.hub_velocity);
  }
  domain_.set_motion(m);
  if (times) times->motion += seconds_since(t);
  domain_.set_rotor_forces(s.harmonics);
  if (times) times->forces += seconds_since(t);
  have_previous_ = true;
  previous_time_ = s.time;
  previous_velocity_ = s.hub_velocity;
  previous_rate_ = s.body_rate;
}

void LrmInflow::reset(const rotor::RotorDiskState& state) {
  take(state);
  if (!started_) {
    domain_.restart_flow();
    domain_.step(std::max(1L, static_cast<long>(std::lround(warm_up_ / domain_.time_step()))));
    started_ = true;
  }
  time_ = domain_.time();
  inflow_ = domain_.inflow();
}

long LrmInflow::steps_due(double dt) const {
  if (!started_) return 0;
  // whole LBM steps up to the flight model's time (one per coupling step at N = 64: both 1.80352 ms)
  return static_cast<long>(std::floor((time_ + dt - domain_.time()) / domain_.time_step() + 0.5));
}

void LrmInflow::skip(double dt) {
  if (!started_ || !(dt > 0)) return;
  const long n = steps_due(dt);
  time_ += dt;
  domain_.skip_steps(n);
  if (n > 0) dropped_steps_ += n;
}

void LrmInflow::advance(const rotor::RotorDiskState& state, double dt) {
  if (!started_) reset(state);
  take(state, &times_);
  long n = steps_due(dt);
  if (catch_up_limit_ > 0 && n > catch_up_limit_) {  // drop the backlog: only the newest steps run
    const double dropped = dt * static_cast<double>(n - catch_up_limit_) / static_cast<double>(n);
    skip(dropped);
    dt -= dropped;
    n = steps_due(dt);
  }
  time_ += dt;
  if (n <= 0) return;  // a coarse lattice steps less often; the last inflow holds meanwhile
  auto t = Clock::now();
  domain_.step(n);
  if (time_parts_) domain_.solver().synchronize();
  times_.lbm += seconds_since(t);
  inflow_ = domain_.inflow();
  times_.inflow += seconds_since(t);
}

}  // namespace ship_lrm::lrm
