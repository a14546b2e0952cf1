#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <memory>

#include "ship_lrm/lbm/benchmark.hpp"

namespace ship_lrm::lbm {

namespace {
// Best of several timed passes of kernel(a, b, n) over arrays of at least 256 MiB (so that they
// stream from memory, not from the caches); returns GB/s counting 2 * n * 4 bytes per pass.
template <typename Kernel>
double host_bandwidth(std::size_t bytes, Kernel kernel) {
  const std::size_t n = std::max<std::size_t>(bytes, std::size_t(256) << 20) / sizeof(float);
  std::unique_ptr<float[]> a(new float[n]), b(new float[n]);
  const long ln = static_cast<long>(n);
#pragma omp parallel for schedule(static)
  for (long i = 0; i < ln; ++i) a[i] = 1.0f, b[i] = 0.0f;  // first touch by the thread that works on it
  double best = 1e30;
  for (int rep = 0; rep < 6; ++rep) {
    const auto t0 = std::chrono::steady_clock::now();
    kernel(a.get(), b.get(), ln);
    const auto t1 = std::chrono::steady_clock::now();
    if (rep > 0) best = std::min(best, std::chrono::duration<double>(t1 - t0).count());
  }
  volatile float sink = a[n / 2] + b[n / 2];
  (void)sink;
  return 2.0 * n * sizeof(float) / best * 1e-9;
}
}  // namespace

// STREAM "copy" b = a. As in STREAM, 8 bytes per element are counted although the store's cache
// line is also read first (write-allocate), so the hardware moves about 12.
double host_copy_bandwidth_gbs(std::size_t bytes) {
  return host_bandwidth(bytes, [](float* a, float* b, long n) {
#pragma omp parallel for schedule(static)
    for (long i = 0; i < n; ++i) b[i] = a[i];
  });
}

// In-place update a = 1.0001 a: read and write of the same location, the access pattern of the
// in-place AA streaming (no write-allocate traffic).
double host_inplace_bandwidth_gbs(std::size_t bytes) {
  return host_bandwidth(bytes, [](float* a, float*, long n) {
#pragma omp parallel for schedule(static)
    for (long i = 0; i < n; ++i) a[i] *= 1.0001f;
  });
}

}  // namespace ship_lrm::lbm
