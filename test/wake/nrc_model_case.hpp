// The NRC wind-tunnel case's set-up shared by the wake tests (thesis 7.1): the 1/50 NatoGD model in a
// 9.77 m/s stream at the model's air density, on the CPU backend, at a given coarse resolution.
#pragma once
#include <string>

#include "ship_lrm/wake/wake_precompute.hpp"

namespace ship_lrm::test {

inline wake::PrecomputeOptions nrc_model_case(const std::string& motion, int cells_per_length) {
  wake::PrecomputeOptions o;
  o.ship = "natogd";
  o.scale = "model";
  o.motion = motion;
  o.domain.cells_per_length = cells_per_length;
  o.domain.wind = 9.77;
  o.domain.density = 1.225;  // thesis table 6.2
  o.domain.backend = lbm::Backend::Cpu;
  return o;
}

}  // namespace ship_lrm::test
