// Paces a simulation to the wall clock (real-time runs of the approach: `ship_lrm approach
// --realtime` and the ROS FlightModel with realtime:=true). Simulated time t is due at start + t.
// A loop gives each step its deadline (due(t + dt), e.g. ShipApproach::set_deadline), steps, then
// waits for it: a step that ends after its due time is counted as an overrun and the loop goes on at
// once, catching up without sleeping (the simulated time is never stretched or skipped).
#pragma once
#include <chrono>
#include <thread>

namespace ship_lrm::lrm {

class WallClockPacer {
 public:
  using clock = std::chrono::steady_clock;
  // simulated time t0 is due now
  explicit WallClockPacer(double t0 = 0.0) : start_(clock::now() - seconds(t0)) {}
  clock::time_point due(double t) const { return start_ + seconds(t); }
  // Sleeps until simulated time t is due; false (and counted) when that time has already passed.
  bool wait_until(double t) {
    const clock::time_point d = due(t);
    if (clock::now() > d) {
      ++overruns_;
      return false;
    }
    std::this_thread::sleep_until(d);
    return true;
  }
  long overruns() const { return overruns_; }
  // wall-clock seconds since simulated time 0 was due
  double elapsed() const { return std::chrono::duration<double>(clock::now() - start_).count(); }

 private:
  static clock::duration seconds(double s) { return std::chrono::duration_cast<clock::duration>(std::chrono::duration<double>(s)); }
  clock::time_point start_;
  long overruns_ = 0;
};

}  // namespace ship_lrm::lrm
