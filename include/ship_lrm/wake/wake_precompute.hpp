// The ship-wake precompute (thesis 6.2, 6.3, 7): runs a ShipWakeDomain through a start-up
// period, then writes the tabulated region to a wake table at a set interval, and keeps the
// centre-plane statistics of thesis figs. 7.2, 7.3 (mean velocity, turbulent kinetic energy) and, for
// a periodic ship motion, their phase averages at 0, 1/4, 1/2 and 3/4 of the period (fig. 7.6).
// Checkpoints at a wall-clock interval (and when asked to stop) let a stopped run resume without
// losing more than that interval; the table then keeps the frames the checkpoint had written.
#pragma once
#include <atomic>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "ship_lrm/wake/wake_domain.hpp"

namespace ship_lrm::wake {

struct PrecomputeOptions {
  WakeConfig domain;
  std::string ship = "natogd";              // natogd | sfs2 | FILE.stl
  std::string scale = "full";               // model (1/50) | full
  std::string motion = "static";            // static | pitch | heave | approach | FILE.csv
  double startup = -1;                      // s; < 0: the time the wind takes to cross the domain once
  double duration = 30;                     // s of frames after the start-up
  double frame_interval = 0.02;             // s (thesis 6.3)
  double stats_interval = -1;               // s between centre-plane samples; < 0: the frame interval
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

struct CentrePlaneStats {
  int nx = 0, nz = 0;
  std::vector<double> x, z;  // ship-frame coordinates
  std::vector<std::uint8_t> solid;
  long samples = 0;
  std::vector<double> sum, sum_sq;  // 3 per point
  // phase ensembles (periodic motion only): 4 of them
  std::array<long, 4> phase_samples{0, 0, 0, 0};
  std::array<std::vector<double>, 4> phase_sum, phase_sum_sq;
  void add(const ShipWakeDomain::Plane& p, int phase = -1);  // phase -1: the overall statistics, 0..3: that phase's ensemble
  // mean velocity (3 per point) and TKE = (var u + var v + var w) / 2 of the samples (or one phase)
  std::vector<float> mean(int phase = -1) const;
  std::vector<float> tke(int phase = -1) const;
};

struct PrecomputeResult {
  std::string table, xdmf, centre_plane_csv;
  int frames = 0;
  long steps = 0;
  double simulated = 0, wall_seconds = 0, mlups = 0;
  bool resumed = false, interrupted = false;
  std::size_t cells = 0, rebuilds = 0;
  double dx = 0, dt = 0;
  CentrePlaneStats stats;
};

// Throws lbm::ConfigError / GeometryError / MotionError / TableError for bad input before any step.
PrecomputeResult precompute_wake(const PrecomputeOptions& opt);

// Named presets: "default" (the approach scenario's table: NatoGD full scale, the approach
// wind and ship motion, N = 48, 30 s of frames every 0.1 s; a few minutes on 2 cores) and "tiny" (a
// small table for tests, seconds). ConfigError for other names.
PrecomputeOptions preset(const std::string& name);
// Where the "default" preset's table is cached: $SHIP_LRM_WAKE_CACHE/wake_default_v3.h5, else
// ~/.cache/ship_lrm/wake_default_v3.h5 (made by `ship_lrm wake --preset default`).
std::string default_table_path();

}  // namespace ship_lrm::wake
