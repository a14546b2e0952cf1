// `ship_lrm validate cylinder`: the Schaefer & Turek 3D-1Z drag benchmark at a chosen resolution.
// `ship_lrm validate stream-stability`: does a disturbed uniform stream stay uniform (stream_stability.hpp)?
// `ship_lrm validate nrc-deck` (with the wake module): cmd_validate_nrc_deck.cpp.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>

#include "commands.hpp"
#include "ship_lrm/lbm/cylinder_benchmark.hpp"
#include "ship_lrm/lbm/stream_stability.hpp"

namespace ship_lrm::tools {

namespace {

std::function<int()> add_stream_stability_command(CLI::App& validate) {
  auto* cmd = validate.add_subcommand(
      "stream-stability",
      "A periodic box of uniform stream with a small disturbance: does the disturbance decay? (BGK near tau = 1/2 is unstable above a "
      "lattice Mach number of a few tenths; Lallemand & Luo 2000)");
  struct Opts {
    std::string machs = "0.15,0.225,0.3";
    float nu = 1.37e-7f;
    float smagorinsky = 0.05f;
    std::string collision = "bgk";
    std::string faces = "periodic";
    bool characteristic = false;
    int absorbing = 0;
    int size = 32;
    long steps = 2000;
    float amplitude = 1e-4f;
    std::string seed = "random";
    std::string backend = "auto";
    std::string csv;
    bool overwrite = false;
  };
  auto o = std::make_shared<Opts>();
  cmd->add_option("--mach", o->machs, "stream speeds U / c_s, a comma list")->capture_default_str();
  cmd->add_option("--nu", o->nu, "lattice viscosity (the LRM's for air: 1.37e-7 at N = 32, 6.8e-8 at N = 64)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  cmd->add_option("--smagorinsky", o->smagorinsky, "Smagorinsky constant s (the LRM's: 0.05; 0: none)")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  cmd->add_option("--collision", o->collision, "bgk or recursive (recursive regularised, Coreixas et al. 2017)")
      ->check(CLI::IsMember({"bgk", "recursive"}))
      ->capture_default_str();
  cmd->add_option("--faces", o->faces,
                  "periodic (the collision alone) or inlet-outlet (velocity inlet at -x, pressure outlet at +x, y and z periodic)")
      ->check(CLI::IsMember({"periodic", "inlet-outlet"}))
      ->capture_default_str();
  cmd->add_flag("--characteristic-inlet", o->characteristic, "inlet-outlet: a characteristic (non-reflecting) velocity inlet");
  cmd->add_option("--absorbing-layer", o->absorbing, "inlet-outlet: an absorbing layer of this many cells inside the inlet (strength 0.5)")
      ->check(CLI::Range(0, 64))
      ->capture_default_str();
  cmd->add_option("--size", o->size, "cells per edge of the periodic box")->check(CLI::Range(4, 512))->capture_default_str();
  cmd->add_option("--steps", o->steps, "steps per case")->check(CLI::Range(1L, 100000000L))->capture_default_str();
  cmd->add_option("--amplitude", o->amplitude, "disturbance, lattice velocity units")->check(CLI::Range(1e-8, 1e-2))->capture_default_str();
  cmd->add_option("--seed", o->seed, "random (every component) or shear (u_x + a sin(2 pi y / size), decays as exp(-nu k^2 t))")
      ->check(CLI::IsMember({"random", "shear"}))
      ->capture_default_str();
  cmd->add_option("--backend", o->backend, "cpu, cuda or auto")->check(CLI::IsMember({"cpu", "cuda", "auto"}))->capture_default_str();
  cmd->add_option("--csv", o->csv, "also write every sample (mach, step, max |u - U|, seeded-mode amplitude) to this CSV file");
  cmd->add_flag("--overwrite", o->overwrite, "replace an existing --csv file");
  return [o, cmd]() -> int {
    if (!cmd->parsed()) return -1;
    const std::vector<double> machs = parse_number_list(o->machs, "--mach", 0.0, lbm::kMaxSetupMach, "");
    std::ofstream csv;
    if (!o->csv.empty()) {
      check_output_file(o->csv, "--csv", o->overwrite);
      csv.open(o->csv);
      if (!csv) throw ConfigError("validate stream-stability: cannot write " + o->csv);
      csv << "mach,step,max_deviation,seeded_mode\n";
    }
    std::printf("%-6s %-10s %-12s %-12s %s\n", "Mach", "steps", "max|u-U| 0", "max|u-U| end", "verdict");
    for (double mach : machs) {
      lbm::StreamStabilityCase c;
      c.size = o->size;
      c.mach = static_cast<float>(mach);
      c.nu = o->nu;
      c.smagorinsky = o->smagorinsky;
      c.collision = lbm::parse_collision_model(o->collision);
      c.characteristic_inlet = o->characteristic;
      c.absorbing_cells = o->absorbing;
      c.faces = o->faces == "periodic" ? lbm::StreamStabilityCase::Faces::Periodic : lbm::StreamStabilityCase::Faces::InletOutlet;
      c.amplitude = o->amplitude;
      c.seed = o->seed == "shear" ? lbm::StreamStabilityCase::Seed::ShearWave : lbm::StreamStabilityCase::Seed::Random;
      c.steps = o->steps;
      c.sample_interval = std::max(1L, o->steps / 8);
      c.backend = lbm::parse_backend(o->backend);
      const lbm::StreamStabilityResult r = lbm::run_stream_stability(c);
      for (const auto& s : r.samples) csv << mach << ',' << s.step << ',' << s.max_deviation << ',' << s.shear_amplitude << '\n';
      const auto& first = r.samples.front();
      const double U = mach / std::sqrt(3.0);
      if (r.diverged) {
        std::printf("%-6.3f %-10ld %-12.3e %-12s diverged at step %ld\n", mach, r.diverged_at, first.max_deviation, "-", r.diverged_at);
        continue;
      }
      const auto& last = r.samples.back();
      std::printf("%-6.3f %-10ld %-12.3e %-12.3e %s (x %.3g; %.2g %% of U)\n", mach, last.step, first.max_deviation, last.max_deviation,
                  r.growth() > 1.0 ? "GROWS" : "decays", r.growth(), U > 0 ? 100.0 * last.max_deviation / U : 0.0);
    }
    return 0;
  };
}

}  // namespace

std::function<int()> add_validate_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("validate", "Validation cases: the LBM core, the NRC deck case");
  cmd->require_subcommand(1);
  auto* cyl = cmd->add_subcommand("cylinder",
                                  "Schaefer & Turek 1996 case 3D-1Z: drag of a cylinder in a channel at Re = 20 (reference c_D = 6.18533)");
  struct Opts {
    int resolution = 10;
    std::string backend = "auto";
    long max_steps = 400000;
    double tolerance = 1e-3;
    std::string vti;
    bool overwrite = false;
  };
  auto o = std::make_shared<Opts>();
  cyl->add_option("--resolution", o->resolution, "cells per cylinder diameter")->check(CLI::Range(4, 80))->capture_default_str();
  cyl->add_option("--backend", o->backend, "cpu, cuda or auto")->check(CLI::IsMember({"cpu", "cuda", "auto"}))->capture_default_str();
  cyl->add_option("--max-steps", o->max_steps, "stop after this many steps")->check(CLI::PositiveNumber)->capture_default_str();
  cyl->add_option("--tolerance", o->tolerance, "relative change of c_D that counts as converged")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  cyl->add_option("--vti", o->vti, "write the final flow field to this .vti file (ParaView)");
  cyl->add_flag("--overwrite", o->overwrite, "replace an existing --vti file");
  auto stability = add_stream_stability_command(*cmd);
#ifdef SHIP_LRM_HAVE_FLIGHT
  auto nrc_deck = add_nrc_deck_command(*cmd);
#else
  std::function<int()> nrc_deck = [] { return -1; };
#endif
  return [o, cyl, stability, nrc_deck]() -> int {
    if (const int r = stability(); r >= 0) return r;
    if (const int r = nrc_deck(); r >= 0) return r;
    if (!cyl->parsed()) return -1;
    check_output_file(o->vti, "--vti", o->overwrite);
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
