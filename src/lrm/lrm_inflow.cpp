// The LRM domain behind the rotor-inflow interface (see lrm_inflow.hpp).
#include "ship_lrm/lrm/lrm_inflow.hpp"

#include <cmath>

namespace ship_lrm::lrm {

LrmInflow::LrmInflow(const LrmConfig& cfg, double warm_up) : domain_(cfg), warm_up_(warm_up) {}

void LrmInflow::take(const rotor::RotorDiskState& s) {
  domain_.set_stream(-s.hub_velocity);
  domain_.set_rotor_forces(s.harmonics);
  body_rate_ = s.body_rate;
  radius_ = s.radius;
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
  rotor::add_frame_rotation(inflow_, body_rate_, radius_);
}

void LrmInflow::advance(const rotor::RotorDiskState& state, double dt) {
  if (!started_) reset(state);
  take(state);
  time_ += dt;
  // whole LBM steps up to the flight model's time (one per coupling step at N = 64: both 1.80352 ms)
  const long n = static_cast<long>(std::floor((time_ - domain_.time()) / domain_.time_step() + 0.5));
  if (n <= 0) return;  // a coarse lattice steps less often; the last inflow holds meanwhile
  domain_.step(n);
  inflow_ = domain_.inflow();
  rotor::add_frame_rotation(inflow_, body_rate_, radius_);
}

}  // namespace ship_lrm::lrm
