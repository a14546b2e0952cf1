#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <memory>

#include "ship_lrm/lbm/benchmark.hpp"

namespace ship_lrm::lbm {

double host_copy_bandwidth_gbs(std::size_t bytes) {
  // at least 256 MiB per array so that the copy streams from memory, not from the caches
  const std::size_t n = std::max<std::size_t>(bytes, std::size_t(256) << 20) / sizeof(float);
  std::unique_ptr<float[]> a(new float[n]), b(new float[n]);
  const long ln = static_cast<long>(n);
#pragma omp parallel for schedule(static)
  for (long i = 0; i < ln; ++i) a[i] = 1.0f, b[i] = 0.0f;  // first touch by the thread that copies
  double best = 1e30;
  for (int rep = 0; rep < 6; ++rep) {
    const auto t0 = std::chrono::steady_clock::now();
#pragma omp parallel for schedule(static)
    for (long i = 0; i < ln; ++i) b[i] = a[i];
    const auto t1 = std::chrono::steady_clock::now();
    if (rep > 0) best = std::min(best, std::chrono::duration<double>(t1 - t0).count());
  }
  volatile float sink = b[n / 2];
  (void)sink;
  return 2.0 * n * sizeof(float) / best * 1e-9;
}

}  // namespace ship_lrm::lbm
