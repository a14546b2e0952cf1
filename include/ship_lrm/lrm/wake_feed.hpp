// Feeding the LRM's faces from a ship-wake table (thesis 5.2, 6.3): every open-boundary cell
// of the LRM domain gets the table's air velocity at its position (trilinear in space, linear in time),
// relative to the hub and in the domain's axes; the velocity faces impose it, the impedance faces take
// it as their reference flow.
#pragma once
#include <memory>
#include <string>

#include "ship_lrm/lrm/domain.hpp"
#include "ship_lrm/lrm/ship_walls.hpp"
#include "ship_lrm/wake/wake_table.hpp"

namespace ship_lrm::lrm {

class WakeFaceFeed {
 public:
  explicit WakeFaceFeed(std::shared_ptr<wake::WakeTable> table);
  // Where the domain is in the table's mean frame (hub, rotation, hub velocity; its own rotation and
  // accelerations reach the domain through LrmDomain::set_motion as before).
  using Pose = DomainPose;
  // Passes the table's frames around time t (table time), for the window around the domain, to the
  // domain (LrmDomain::set_face_grid: every boundary cell interpolated, on the GPU where the faces
  // live there), when the faces are due: the table time moved on by a quarter frame interval, or the domain by a quarter
  // cell or by a quarter cell's angle at its edge, since the last refresh (the thesis holds a frame for
  // its whole 0.02 s interval, thesis 6.3). Returns whether it refreshed. force: refresh now.
  bool apply(LrmDomain& domain, double t, const Pose& pose, bool force = false);
  const wake::WakeTable& table() const { return *table_; }

 private:
  std::shared_ptr<wake::WakeTable> table_;
  const LrmDomain* domain_ = nullptr;
  bool fed_ = false;
  double last_t_ = 0;
  Pose last_;
};

// Cost of serving the faces against the LRM step (face-feed cost target): an LRM domain whose hub flies
// at `speed` m/s towards the bow, `height` m above the landing spot (x = -12.75 m full scale), through
// the table; the faces are refreshed before every LBM step.
struct WakeFeedBenchmark {
  std::string backend;
  int nodes = 0, cells_per_edge = 0, steps = 0;
  std::size_t boundary_cells = 0, window_loads = 0, read_ahead_hits = 0, refreshes = 0;
  double step_seconds = 0, feed_seconds = 0;  // per LBM step
  double feed_fraction() const { return feed_seconds / step_seconds; }
  // The same in the loop as the coupled runs step it, without waiting for the device between feed and
  // step (above, each is timed to its end, which on a GPU adds a synchronisation's round trip to the
  // feed): the wall time per step of the faces fed and stepped, and of the steps alone with the faces
  // held (the best of two alternating runs of `steps` steps each).
  double loop_fed_seconds = 0, loop_alone_seconds = 0;
  double loop_feed_fraction() const { return loop_fed_seconds / loop_alone_seconds - 1.0; }
  std::string to_json() const;
};
WakeFeedBenchmark run_wake_feed_benchmark(const std::string& table, const LrmConfig& cfg, int steps, double speed = 5.0,
                                          double height = 8.0);

}  // namespace ship_lrm::lrm
