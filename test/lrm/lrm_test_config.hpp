// The quick LRM set-up of the CI tests: N = 32, a = 1.25 (thesis 6.4 domain at half resolution), CPU.
#pragma once

#include "ship_lrm/lrm/domain.hpp"

namespace ship_lrm::lrm::test {

inline LrmConfig quick_config(int nodes = 32, double reach = 1.25) {
  LrmConfig c;
  c.nodes = nodes;
  c.reach = reach;
  c.backend = lbm::Backend::Cpu;
  return c;
}

}  // namespace ship_lrm::lrm::test
