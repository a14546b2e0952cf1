// Tells a real-time run's user when the machine cannot keep the LRM's deadlines (real-time
// target; docs/benchmarks.md at 193c1b4, "A slower VM"). A paced run whose LRM is too slow does not fail:
// each late step flies on Pitt-Peters (RealTimeInflow), and the loads look plausible. On a 2-core VM
// that ran the N = 32 step at half the usual speed, 81 - 99.8 % of the steps did so, which the
// diagnostics counted but nothing said aloud. The watch looks at windows of simulated time and
// returns a message for each window in which most steps missed their deadline.
#pragma once

#include <string>

#include "ship_lrm/lrm/realtime_inflow.hpp"

namespace ship_lrm::lrm {

class DeadlineWatch {
 public:
  // window_s: simulated seconds per window (> 0); threshold: the fraction of a window's steps that
  // must miss (0 .. 1) for it to be reported.
  explicit DeadlineWatch(double window_s = 5.0, double threshold = 0.5);
  // After each step, with the simulated time and the run's totals so far: the message when a window
  // ended at or before t with more than `threshold` of its steps missed, else empty.
  std::string update(double t, const RealTimeStats& totals);
  // Windows reported so far.
  int reports() const { return reports_; }

 private:
  double window_s_, threshold_;
  double window_start_ = 0, window_end_;  // simulated time where the counted steps began, and where the window ends
  long steps_at_start_ = 0, misses_at_start_ = 0;
  int reports_ = 0;
};

}  // namespace ship_lrm::lrm
