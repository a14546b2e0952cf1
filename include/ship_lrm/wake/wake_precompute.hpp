// The ship-wake precompute (thesis 6.2, 6.3, 7): runs a ShipWakeDomain (and its fine region, if
// any) through a start-up period, then writes the tabulated region (and the fine level: a nested
// table) to a wake table at a set interval, and keeps the statistics of wake_statistics.hpp: the
// centre plane of each level (thesis figs. 7.2, 7.3, 7.6) and the time series at probe points.
// Checkpoints at a wall-clock interval (and when asked to stop) let a stopped run resume without
// losing more than that interval; the table then keeps the frames the checkpoint had written.
#pragma once
#include <atomic>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "ship_lrm/wake/wake_domain.hpp"
#include "ship_lrm/wake/wake_statistics.hpp"

namespace ship_lrm::wake {

struct PrecomputeOptions {
  WakeConfig domain;
  std::string ship = "natogd";    // natogd | sfs2 | FILE.stl
  std::string scale = "full";     // model (1/50) | full
  std::string motion = "static";  // static | pitch | heave | approach | FILE.csv
  double startup = -1;            // s; < 0: the time the wind takes to cross the domain once
  double duration = 30;           // s of frames after the start-up
  double frame_interval = 0.02;   // s (thesis 6.3)
  double stats_interval = -1;     // s between statistics samples (centre planes, probes); < 0: the frame interval
  // Probe points (m, ship frame of the mean pose: x forward, y starboard, z down), sampled from the
  // finest level that covers each; ConfigError before any step for a probe that is not in the fluid.
  std::vector<std::array<double, 3>> probes;
  // Probes fixed to the ship (as the NRC model's COBRA probes, thesis 7.1): each is a point of the
  // moving ship and records the air relative to it in the ship's axes. Off: fixed points of the mean
  // frame, recording the air in the mean frame (the same for a static ship).
  bool probes_on_ship = false;
  bool half_precision = true;               // float16 on disk
  std::string out;                          // table path (.h5); the side-car .xdmf and the checkpoint .ckpt beside it
  double checkpoint_seconds = 60;           // wall-clock interval between checkpoints
  bool resume = true;                       // continue from a matching checkpoint
  const std::atomic<bool>* stop = nullptr;  // set (e.g. by SIGINT): checkpoint and return
  long stop_at_step = -1;                   // >= 0: checkpoint and return at this step (tests)
  struct Progress {
    double fraction, sim_time, eta_seconds, mlups;
    int frames;
  };
  std::function<void(const Progress&)> progress;  // called about once a second
};

struct PrecomputeResult {
  std::string table, xdmf, centre_plane_csv;
  std::string fine_centre_plane_csv, probes_csv;  // with a fine region; with probes
  int frames = 0;
  long steps = 0;
  double simulated = 0, wall_seconds = 0, mlups = 0;
  bool resumed = false, interrupted = false;
  std::size_t cells = 0, rebuilds = 0;
  double dx = 0, dt = 0;
  CentrePlaneStats stats;
  // the fine region (fine_cells 0 without one), and the wall time of each level's steps
  std::size_t fine_cells = 0;
  double fine_dx = 0, coarse_seconds = 0, fine_seconds = 0, coarse_mlups = 0, fine_mlups = 0;
  CentrePlaneStats fine_stats;
  ProbeSeries probes;
};

// Throws ConfigError / GeometryError / MotionError / TableError for bad input before any step.
PrecomputeResult precompute_wake(const PrecomputeOptions& opt);

// Named presets: "default" (the approach scenario's table: NatoGD full scale, the approach
// wind and ship motion, N = 48, 30 s of frames every 0.1 s; under a minute on 2 cores), "realistic"
// (the same with a fine region over the superstructure at 364 cells per ship length, the deck and the
// end of the approach stored at that resolution; docs/benchmarks.md states its cost) and "tiny" (a
// small table for tests, seconds). ConfigError for other names.
PrecomputeOptions preset(const std::string& name);
// Where a preset's table is cached: $SHIP_LRM_WAKE_CACHE/FILE, else ~/.cache/ship_lrm/FILE, FILE
// wake_default_v3.h5 or wake_realistic_v1.h5 (made by `ship_lrm wake --preset NAME`). ConfigError for
// a preset without a cached table.
std::string preset_table_path(const std::string& name);
std::string default_table_path();  // preset_table_path("default")
// The table a user names (`ship_lrm approach --wake`, the ROS parameter wake_file): empty or "default"
// the default preset's cached table, "realistic" the realistic one's (unless a file of that name is
// here), else the path as given. `preset` is set to the preset's name, or cleared.
std::string named_table(const std::string& given, std::string& preset);
// "the default wake table PATH does not exist yet; make it with `ship_lrm wake --preset default`", or
// for a path that is no preset's, that it was not found and the command that makes one there.
std::string missing_table_message(const std::string& path, const std::string& preset);

}  // namespace ship_lrm::wake
