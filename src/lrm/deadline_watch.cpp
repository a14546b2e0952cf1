#include "ship_lrm/lrm/deadline_watch.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace ship_lrm::lrm {

DeadlineWatch::DeadlineWatch(double window_s, double threshold) : window_s_(window_s), threshold_(threshold), window_end_(window_s) {
  if (!(window_s > 0) || !std::isfinite(window_s)) throw std::invalid_argument("DeadlineWatch: the window must be a positive time");
  if (!(threshold >= 0 && threshold <= 1)) throw std::invalid_argument("DeadlineWatch: the threshold must lie in [0, 1]");
}

std::string DeadlineWatch::update(double t, const RealTimeStats& totals) {
  if (t < window_end_) return {};
  const long steps = totals.steps - steps_at_start_, misses = totals.deadline_misses - misses_at_start_;
  const double from = window_start_;  // where the counts below began (a long step may span windows)
  window_start_ = t;
  steps_at_start_ = totals.steps;
  misses_at_start_ = totals.deadline_misses;
  while (window_end_ <= t) window_end_ += window_s_;  // the next window ends after t
  if (steps <= 0 || static_cast<double>(misses) <= threshold_ * static_cast<double>(steps)) return {};
  ++reports_;
  char text[400];
  std::snprintf(text, sizeof text,
                "%ld of %ld steps (%.0f %%) from t = %.1f to %.1f s missed their LRM deadline and flew on Pitt-Peters: "
                "this machine does not run this LRM domain in real time. A GPU (backend cuda), a smaller N, or "
                "simulated time (no real-time pacing) keep the LRM inflow.",
                misses, steps, 100.0 * static_cast<double>(misses) / static_cast<double>(steps), from, t);
  return text;
}

}  // namespace ship_lrm::lrm
