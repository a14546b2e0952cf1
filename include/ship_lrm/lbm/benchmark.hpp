// LBM throughput benchmark and a STREAM-like copy bandwidth measurement (McCalpin, "STREAM:
// Sustainable Memory Bandwidth in High Performance Computers"): the roofline of a memory-bound LBM
// is bandwidth / bytes moved per cell update.
#pragma once

#include <string>

#include "ship_lrm/lbm/solver.hpp"

namespace ship_lrm::lbm {

// STREAM "copy" bandwidth in GB/s (bytes read + written), best of several repetitions, on the
// host with all OpenMP threads (bytes: array size in bytes).
double host_copy_bandwidth_gbs(std::size_t bytes);
// In-place read-modify-write a[i] = s a[i] (the AA pattern's access: no write-allocate traffic),
// counted like copy (8 bytes per element).
double host_inplace_bandwidth_gbs(std::size_t bytes);
// Same on the CUDA device (ConfigError without CUDA).
double device_copy_bandwidth_gbs(std::size_t bytes);
double device_inplace_bandwidth_gbs(std::size_t bytes);

struct LbmBenchmarkResult {
  std::string backend;
  int size = 0;
  long steps = 0;
  double seconds = 0;
  double mlups = 0;  // million lattice (cell) updates per second
  double us_per_step = 0;
  double bytes_per_cell_update = 0;  // populations read + written + cell type
  double bandwidth_gbs = 0;          // STREAM-like copy in the same run
  double roofline_fraction = 0;      // mlups / (bandwidth / bytes_per_cell_update)
  double inplace_bandwidth_gbs = 0;  // in-place read-modify-write in the same run
  double roofline_fraction_inplace = 0;
  int threads = 1;
  std::string to_json() const;
};

// Periodic N^3 box (a Taylor-Green start), BGK (or Smagorinsky if s > 0). steps <= 0: choose a
// count that runs for about min_seconds.
LbmBenchmarkResult run_lbm_benchmark(Backend backend, int size, long steps, float smagorinsky = 0.0f, double min_seconds = 2.0);

}  // namespace ship_lrm::lbm
