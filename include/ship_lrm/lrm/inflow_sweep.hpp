// Isolated rotor in the LRM domain (thesis 8.1): a uniformly loaded disk at zero incidence in a
// stream, its time-averaged inflow against Pitt-Peters / momentum theory.
#pragma once

#include "ship_lrm/lrm/domain.hpp"

namespace ship_lrm::lrm {

struct IsolatedRotorCase {
  double speed = 0;           // m/s edgewise stream (the rotor flies forward at this speed)
  double thrust = 24525;      // N, uniform over the disk (thesis 8.1: Bo 105 CBS-5 MTOW)
  double settle = 4.0;        // s simulated before averaging
  double average = 2.0;       // s averaged
  double rotor_speed = 44.4;  // rad/s, only to non-dimensionalise the Pitt-Peters reference
};

struct IsolatedRotorResult {
  rotor::RotorInflow inflow;                            // time average, m/s (relative to the domain)
  double induced_mean = 0;                              // inflow.mean.z (the stream has no z component)
  double pitt_peters_mean = 0, pitt_peters_cosine = 0;  // m/s, steady Pitt-Peters for the same load
  double momentum_theory = 0;                           // m/s, Glauert / hover momentum theory
  long steps = 0;
  double wall_seconds = 0, simulated_seconds = 0;
  int cells_per_edge = 0;
};

IsolatedRotorResult run_isolated_rotor(const LrmConfig& cfg, const IsolatedRotorCase& c);

}  // namespace ship_lrm::lrm
