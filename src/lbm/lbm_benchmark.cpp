#include <omp.h>

#include <chrono>
#include <cmath>
#include <sstream>

#include "ship_lrm/lbm/benchmark.hpp"

namespace ship_lrm::lbm {

std::string LbmBenchmarkResult::to_json() const {
  std::ostringstream s;
  s << "{\"backend\": \"" << backend << "\", \"size\": " << size << ", \"steps\": " << steps << ", \"seconds\": " << seconds
    << ", \"mlups\": " << mlups << ", \"us_per_step\": " << us_per_step << ", \"bytes_per_cell_update\": " << bytes_per_cell_update
    << ", \"bandwidth_gbs\": " << bandwidth_gbs << ", \"roofline_fraction\": " << roofline_fraction
    << ", \"inplace_bandwidth_gbs\": " << inplace_bandwidth_gbs << ", \"roofline_fraction_inplace\": " << roofline_fraction_inplace
    << ", \"threads\": " << threads << "}";
  return s.str();
}

LbmBenchmarkResult run_lbm_benchmark(Backend backend, int size, long steps, float smagorinsky, double min_seconds) {
  if (size < 8 || size > 1024) throw ConfigError("benchmark size must lie in [8, 1024]");
  LatticeConfig cfg;
  cfg.nx = cfg.ny = cfg.nz = size;
  for (auto& f : cfg.faces) f.type = FaceType::Periodic;
  cfg.collision.nu = 0.01f;
  cfg.collision.smagorinsky = smagorinsky;
  cfg.guard_interval = 0;
  auto solver = make_solver(Lattice(cfg), backend);
  // Taylor-Green start so that the collision does real work
  const std::size_t n = solver->lattice().cells();
  std::vector<float> u(3 * n);
  const double k = 2.0 * M_PI / size;
  for (int z = 0; z < size; ++z)
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x) {
        const std::size_t c = solver->lattice().index(x, y, z);
        u[3 * c] = 0.05f * std::sin(k * x) * std::cos(k * y) * std::cos(k * z);
        u[3 * c + 1] = -0.05f * std::cos(k * x) * std::sin(k * y) * std::cos(k * z);
      }
  solver->initialize({}, u);
  solver->step(4);  // warm-up
  solver->synchronize();
  auto timed = [&](long s) {
    const auto t0 = std::chrono::steady_clock::now();
    solver->step(s);
    solver->synchronize();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  };
  if (steps <= 0) {
    steps = 2;
    double t = timed(steps);
    while (t < 0.25 * min_seconds) {
      steps *= 2;
      t = timed(steps);
    }
    steps = std::max<long>(2, static_cast<long>(steps * min_seconds / std::max(t, 1e-9)) & ~1L);
  }
  LbmBenchmarkResult r;
  r.backend = solver->backend_name();
  r.size = size;
  r.steps = steps;
  r.seconds = timed(steps);
  r.mlups = static_cast<double>(n) * steps / r.seconds * 1e-6;
  r.us_per_step = r.seconds / steps * 1e6;
  r.bytes_per_cell_update = 2.0 * Q * sizeof(pop_t) + 1.0;
  const std::size_t bytes = n * Q * sizeof(pop_t);
  const bool gpu = r.backend == "cuda";
  r.bandwidth_gbs = gpu ? device_copy_bandwidth_gbs(bytes) : host_copy_bandwidth_gbs(bytes);
  r.inplace_bandwidth_gbs = gpu ? device_inplace_bandwidth_gbs(bytes) : host_inplace_bandwidth_gbs(bytes);
  r.roofline_fraction = r.mlups * 1e6 * r.bytes_per_cell_update / (r.bandwidth_gbs * 1e9);
  r.roofline_fraction_inplace = r.mlups * 1e6 * r.bytes_per_cell_update / (r.inplace_bandwidth_gbs * 1e9);
  r.threads = r.backend == "cuda" ? 0 : omp_get_max_threads();
  return r;
}

}  // namespace ship_lrm::lbm
