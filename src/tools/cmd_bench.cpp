// `ship_lrm bench lbm`: LBM throughput against the measured memory-bandwidth roofline.
#include <iomanip>
#include <iostream>

#include "commands.hpp"
#include "ship_lrm/lbm/benchmark.hpp"

namespace ship_lrm::tools {

std::function<int()> add_bench_command(CLI::App& app) {
  auto* bench = app.add_subcommand("bench", "Performance benchmarks");
  bench->require_subcommand(1);
  auto* lbm = bench->add_subcommand("lbm", "D3Q19 LBM step throughput (periodic N^3 box) vs. the STREAM-copy roofline");
  struct Opts {
    std::string backend = "auto";
    int size = 128;
    long steps = 0;
    float smagorinsky = 0.0f;
    double seconds = 2.0;
    bool json = false;
  };
  auto o = std::make_shared<Opts>();
  lbm->add_option("--backend", o->backend, "cpu, cuda or auto")->check(CLI::IsMember({"cpu", "cuda", "auto"}));
  lbm->add_option("--size", o->size, "cells per edge N")->check(CLI::Range(8, 1024));
  lbm->add_option("--steps", o->steps, "time steps to time (0: run about --seconds)")->check(CLI::NonNegativeNumber);
  lbm->add_option("--seconds", o->seconds, "target run time when --steps is 0")->check(CLI::PositiveNumber);
  lbm->add_option("--smagorinsky", o->smagorinsky, "Smagorinsky constant (0: plain BGK)")->check(CLI::Range(0.0, 1.0));
  lbm->add_flag("--json", o->json, "print one JSON object");
  return [o, lbm]() -> int {
    if (!lbm->parsed()) return -1;
    const auto r = lbm::run_lbm_benchmark(lbm::parse_backend(o->backend), o->size, o->steps, o->smagorinsky, o->seconds);
    if (o->json) {
      std::cout << r.to_json() << std::endl;
    } else {
      std::cout << std::fixed << std::setprecision(1) << "backend " << r.backend << ", " << r.size << "^3, " << r.steps
                << " steps: " << r.mlups << " MLUPS, " << r.us_per_step << " us/step; copy bandwidth " << r.bandwidth_gbs << " GB/s, "
                << r.bytes_per_cell_update << " B/cell update -> " << std::setprecision(0) << 100.0 * r.roofline_fraction
                << " % of the copy roofline (" << 100.0 * r.roofline_fraction_inplace << " % of the in-place roofline, "
                << std::setprecision(1) << r.inplace_bandwidth_gbs << " GB/s)\n";
    }
    return 0;
  };
}

}  // namespace ship_lrm::tools
