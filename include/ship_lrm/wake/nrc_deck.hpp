// The NRC wind-tunnel deck case (Bludau 2024, 7.1, 7.2): the 1/50 NatoGD model in a 9.77 m/s stream,
// static, pitching 5 deg at 1 Hz or heaving 0.04 m at 1 Hz, with a fine region over the hangar, the
// deck and the approach path nested in the wake domain (fine_region.hpp). Reports what the thesis
// compares: the velocity statistics at its two deck probes (0.3 m aft of the hangar door, 0.07 m above
// the deck, on the centreline and 0.06 m to starboard, wind-tunnel frame of probe_points.hpp), the
// TKE over the deck region of the centre plane and whether the mean flow behind the hangar door is
// reversed. For a moving ship the statistics are the plain ones over the run (the phase averages are
// in the centre-plane CSVs).
#pragma once
#include <array>
#include <atomic>
#include <functional>
#include <string>
#include <vector>

#include "ship_lrm/wake/wake_precompute.hpp"

namespace ship_lrm::wake {

struct NrcDeckOptions {
  std::string motion = "static";   // static | pitch | heave
  int cells_per_length = 364;      // of the fine region (thesis 7.1: 364 converged, 182 not)
  double seconds = 3;              // of statistics after the start-up
  double sample_interval = 0.002;  // s between samples (probes and centre planes)
  double startup = -1;             // s; < 0: the wind's time across the wake domain
  bool quick = false;              // the CI variant: 64 cells per length, 0.3 s (laminar: a check of the pipeline, not of the physics)
  std::vector<std::array<double, 3>> extra_probes;  // wind-tunnel frame, model scale (m), after the thesis' two
  // The fine region, ship lengths (FineRegionConfig): aft, fore, half width, top. The default: 0.3
  // behind the hangar door to 0.8 forward of it (the whole superstructure, to just aft of the stem),
  // 0.13 to either side, up to 0.31 above the waterline (clear of the mast); for a moving ship the
  // fore face is moved past the bow.
  std::array<double, 4> box{-0.3, 0.8, 0.13, 0.31};
  lbm::Backend backend = lbm::Backend::Auto;
  std::string out_dir;  // the table, its CSVs and the result's JSON are written here
  bool resume = true;
  const std::atomic<bool>* stop = nullptr;
  std::function<void(const PrecomputeOptions::Progress&)> progress;
};

// How a fine resolution is nested: the coarse wake domain's cells per ship length and the ratio
// (a divisor of cells_per_length from 2 to 8, with the coarse domain at 24 cells per length or more,
// the coarse resolution nearest 52: 364 = 52 x 7, 546 = 78 x 7). ConfigError when there is none.
std::array<int, 2> nest_resolution(int cells_per_length);

struct NrcDeckProbe {
  std::array<double, 3> position{};  // wind-tunnel frame, m
  long samples = 0;
  std::array<double, 3> mean{};      // m/s, wind-tunnel frame
  std::array<double, 3> variance{};  // m^2/s^2
  double tke_over_u2 = 0;
  double tke_uncertainty = 0;  // standard error of TKE / U^2 from five batch means of the series
};

struct NrcDeckResult {
  NrcDeckOptions options;
  int coarse_cells_per_length = 0, ratio = 0;
  std::array<double, 4> run_box{};  // the fine region as run (ship lengths; the fore face past the bow for a moving ship)
  double wind = 9.77;
  double statistics_seconds = 0;
  std::vector<NrcDeckProbe> probes;
  // the deck region of the fine centre plane: hangar door to stern, up to 0.05 ship lengths above the deck
  double deck_tke_over_u2 = 0;
  long deck_points = 0, reversed_points = 0;  // fluid points there, and those whose mean flow runs forward (against the wind)
  double reversed_max_over_u = 0;             // the largest forward mean velocity there / U
  PrecomputeResult run;
};

// The options as run: with `quick`, its resolution and statistics time in place of the given ones.
NrcDeckOptions with_quick_setting(NrcDeckOptions o);

// Runs the case (ConfigError, GeometryError for bad options before any step); writes the table and
// the centre-plane and probe CSVs into out_dir.
NrcDeckResult run_nrc_deck(const NrcDeckOptions& opt);

}  // namespace ship_lrm::wake
