// `ship_lrm validate cylinder`: the Schaefer & Turek 3D-1Z drag benchmark at a chosen resolution.
#include <cstdio>
#include <iostream>

#include "commands.hpp"
#include "ship_lrm/lbm/cylinder_benchmark.hpp"

namespace ship_lrm::tools {

std::function<int()> add_validate_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("validate", "Validation cases of the LBM core");
  cmd->require_subcommand(1);
  auto* cyl = cmd->add_subcommand("cylinder",
                                  "Schaefer & Turek 1996 case 3D-1Z: drag of a cylinder in a channel at Re = 20 (reference c_D = 6.18533)");
  struct Opts {
    int resolution = 10;
    std::string backend = "auto";
    long max_steps = 400000;
    double tolerance = 1e-3;
    std::string vti;
  };
  auto o = std::make_shared<Opts>();
  cyl->add_option("--resolution", o->resolution, "cells per cylinder diameter")->check(CLI::Range(4, 80))->capture_default_str();
  cyl->add_option("--backend", o->backend, "cpu, cuda or auto")->check(CLI::IsMember({"cpu", "cuda", "auto"}))->capture_default_str();
  cyl->add_option("--max-steps", o->max_steps, "stop after this many steps")->check(CLI::PositiveNumber)->capture_default_str();
  cyl->add_option("--tolerance", o->tolerance, "relative change of c_D that counts as converged")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  cyl->add_option("--vti", o->vti, "write the final flow field to this .vti file (ParaView)");
  return [o, cyl]() -> int {
    if (!cyl->parsed()) return -1;
    const auto r = lbm::run_cylinder_benchmark(
        o->resolution, lbm::parse_backend(o->backend), o->max_steps, o->tolerance,
        [](long step, double cd) { std::printf("step %8ld  c_D %.5f\n", step, cd), std::fflush(stdout); }, o->vti);
    const double err = r.drag_coefficient / lbm::kSchaeferTurek3D1ZDrag - 1.0;
    std::printf("c_D = %.4f (reference %.5f, error %+.2f %%), c_L = %.4f, %ld steps, %.0f s, %.1f MLUPS%s\n", r.drag_coefficient,
                lbm::kSchaeferTurek3D1ZDrag, 100 * err, r.lift_coefficient, r.steps, r.seconds, r.mlups,
                r.relative_change < o->tolerance ? "" : " (NOT converged)");
    return std::abs(err) < 0.05 && r.relative_change < o->tolerance ? 0 : 1;
  };
}

}  // namespace ship_lrm::tools
