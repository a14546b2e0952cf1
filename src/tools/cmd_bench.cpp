// `ship_lrm bench lbm`: LBM throughput against the measured memory-bandwidth roofline.
#include <cmath>
#include <iomanip>
#include <iostream>

#include "commands.hpp"
#include "ship_lrm/lbm/benchmark.hpp"
#ifdef SHIP_LRM_HAVE_FLIGHT
#include "lrm_face_options.hpp"
#include "ship_lrm/flight/flight_benchmark.hpp"
#include "ship_lrm/lrm/lrm_benchmark.hpp"
#include "ship_lrm/lrm/realtime_inflow.hpp"
#include "ship_lrm/lrm/wake_feed.hpp"
#endif

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
#ifdef SHIP_LRM_HAVE_FLIGHT
  auto* flight =
      bench->add_subcommand("flight", "Bo 105 flight model (blade elements + Pitt-Peters) speed, one thread, at the coupling step");
  struct FlightOpts {
    double seconds = 200, speed = 25;
    std::string config;
    bool json = false;
  };
  auto fo = std::make_shared<FlightOpts>();
  flight->add_option("--seconds", fo->seconds, "simulated seconds to time")->check(CLI::Range(0.01, 3600.0))->capture_default_str();
  flight->add_option("--speed", fo->speed, "trimmed speed it flies from, m/s")->check(CLI::Range(0.0, 90.0))->capture_default_str();
  flight->add_option("--config", fo->config, "helicopter parameter file (default: the shipped config/bo105.yaml)");
  flight->add_flag("--json", fo->json, "print one JSON object");
  auto* lrm_cmd = bench->add_subcommand("lrm", "Coupled step (Bo 105 flight model + LRM domain): t_clock / t_sim (thesis 8.3.1)");
  struct LrmOpts {
    std::string backend = "auto";
    int nodes = 64;
    double reach = 1.25, seconds = 2, speed = 25, warm_up = 0.5, yaw_rate = 0;
    bool json = false, realtime = false, pipelined = false;
    LrmFaceOptions faces;
  };
  auto lo = std::make_shared<LrmOpts>();
  lrm_cmd->add_option("--backend", lo->backend, "cpu, cuda or auto")->check(CLI::IsMember({"cpu", "cuda", "auto"}))->capture_default_str();
  lrm_cmd->add_option("--N", lo->nodes, "lattice nodes per 4R")->check(CLI::Range(16, 512))->capture_default_str();
  lrm_cmd->add_option("--reach", lo->reach, "domain edge / 4R")->check(CLI::Range(1.0, 8.0))->capture_default_str();
  lrm_cmd->add_option("--seconds", lo->seconds, "simulated seconds timed")->check(CLI::Range(0.01, 600.0))->capture_default_str();
  lrm_cmd->add_option("--speed", lo->speed, "trimmed speed, m/s")->check(CLI::Range(0.0, 40.0))->capture_default_str();
  lrm_cmd->add_option("--warm-up", lo->warm_up, "simulated seconds before timing")->check(CLI::Range(0.0, 600.0))->capture_default_str();
  lrm_cmd
      ->add_option("--yaw-rate", lo->yaw_rate,
                   "deg/s: the held fuselage turns at this rate, so that the LRM domain rotates and its step includes the "
                   "frame's fictitious forces (a manoeuvre's step; 0: straight flight)")
      ->check(CLI::Range(-90.0, 90.0))
      ->capture_default_str();
  lo->faces.add_to(*lrm_cmd);
  lrm_cmd->add_flag("--json", lo->json, "print one JSON object");
  lrm_cmd->add_flag("--realtime", lo->realtime,
                    "pace the run to the wall clock with firm deadlines (LRM in its own thread, Pitt-Peters for late steps): "
                    "counts deadline misses");
  lrm_cmd->add_flag("--pipelined", lo->pipelined,
                    "with --realtime: the LRM runs " + std::to_string(lrm::kPipelineDepth) +
                        " LBM intervals behind the flight model (a job is due that many LBM steps after its loads were posted) "
                        "instead of lock-step");
  auto* wake_cmd = bench->add_subcommand("wake", "Serving an LRM domain's faces from a wake table, against the LBM step");
  struct WakeOpts {
    std::string table, backend = "cpu";
    int nodes = 64, steps = 20;
    double reach = 1.25;
    bool json = false;
  };
  auto wo = std::make_shared<WakeOpts>();
  wake_cmd->add_option("--table", wo->table, "wake table (ship_lrm wake ...)")->required();
  wake_cmd->add_option("--backend", wo->backend, "cpu, cuda or auto")->check(CLI::IsMember({"cpu", "cuda", "auto"}))->capture_default_str();
  wake_cmd->add_option("--N", wo->nodes, "lattice nodes per 4R")->check(CLI::Range(16, 512))->capture_default_str();
  wake_cmd->add_option("--reach", wo->reach, "domain edge / 4R")->check(CLI::Range(1.0, 8.0))->capture_default_str();
  wake_cmd->add_option("--steps", wo->steps, "LBM steps timed")->check(CLI::Range(1, 100000))->capture_default_str();
  wake_cmd->add_flag("--json", wo->json, "print one JSON object");
#endif
  return [o, lbm
#ifdef SHIP_LRM_HAVE_FLIGHT
          ,
          fo, flight, lo, lrm_cmd, wo, wake_cmd
#endif
  ]() -> int {
#ifdef SHIP_LRM_HAVE_FLIGHT
    if (wake_cmd->parsed()) {
      lrm::LrmConfig c;
      c.nodes = wo->nodes;
      c.reach = wo->reach;
      c.backend = lbm::parse_backend(wo->backend);
      const auto r = lrm::run_wake_feed_benchmark(wo->table, c, wo->steps);
      if (wo->json)
        std::cout << r.to_json() << std::endl;
      else
        std::cout << std::fixed << std::setprecision(3) << "wake faces, " << r.backend << ", N = " << r.nodes << " (" << r.cells_per_edge
                  << "^3 cells, " << r.boundary_cells << " boundary cells): feed " << 1e3 * r.feed_seconds << " ms, LBM step "
                  << 1e3 * r.step_seconds << " ms per step: " << std::setprecision(1) << 100 * r.feed_fraction() << " % (" << r.refreshes
                  << " refreshes in " << r.steps << " steps, " << r.window_loads << " window reads); in the loop without waits "
                  << 100 * r.loop_feed_fraction() << " % (" << std::setprecision(3) << 1e3 * r.loop_fed_seconds << " against "
                  << 1e3 * r.loop_alone_seconds << " ms per step)\n";
      return 0;
    }
    if (lrm_cmd->parsed()) {
      lrm::LrmConfig c;
      c.nodes = lo->nodes;
      c.reach = lo->reach;
      c.backend = lbm::parse_backend(lo->backend);
      lo->faces.apply(c);
      const auto p = flight::load_default_bo105();
      if (lo->pipelined && !lo->realtime) throw ConfigError("bench lrm: --pipelined needs --realtime");
      const auto mode = lo->pipelined ? lrm::RealTimeMode::Pipelined : lrm::RealTimeMode::LockStep;
      const double yaw_rate = lo->yaw_rate * M_PI / 180.0;
      auto r = lo->realtime ? lrm::run_realtime_benchmark(p, c, lo->seconds, lo->speed, lo->warm_up, mode, yaw_rate)
                            : lrm::run_lrm_benchmark(p, c, lo->seconds, lo->speed, lo->warm_up, yaw_rate);
      r.faces = lo->faces.label();
      if (lo->json) {
        std::cout << r.to_json() << std::endl;
      } else {
        std::cout << std::fixed << std::setprecision(3) << "coupled LRM step, " << r.backend << ", N = " << r.nodes << ", a = " << r.reach
                  << " (" << r.cells_per_edge << "^3 cells" << (r.yaw_rate != 0 ? ", turning" : "") << ", faces " << r.faces
                  << "): t_clock / t_sim = " << r.clock_over_sim << ", " << std::setprecision(1) << r.mlups << " MLUPS\n";
        if (r.far_field_builds > 0)
          std::cout << std::setprecision(3) << "rotor far field: its shape computed " << r.far_field_builds << " times, " << r.far_field_s
                    << " s\n";
        if (r.realtime)
          std::cout << std::setprecision(2) << "paced real time: " << r.deadline_misses << " of " << r.flight_steps
                    << " steps missed their deadline (" << 100.0 * r.miss_fraction << " %), Pitt-Peters served them; worst on-time wait "
                    << 1e3 * r.worst_wait_s << " ms\n";
      }
      return 0;
    }
    if (flight->parsed()) {
      const auto p = fo->config.empty() ? flight::load_default_bo105() : flight::load_helicopter_parameters(fo->config);
      const auto r = flight::run_flight_benchmark(p, fo->seconds, fo->speed);
      if (fo->json)
        std::cout << r.to_json() << std::endl;
      else
        std::cout << std::fixed << std::setprecision(2) << "flight model: " << r.steps << " steps of " << 1e3 * r.time_step << " ms in "
                  << r.wall_seconds << " s: " << r.microseconds_per_step << " us/step, " << std::setprecision(0) << r.real_time_factor
                  << " x real time (one thread)\n";
      return 0;
    }
#endif
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
