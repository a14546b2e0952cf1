// `ship_lrm wake`: the ship-wake precompute, its presets, the ship mesh export, and the
// centre-plane plots of thesis figs. 7.2, 7.3 and 7.6 (scripts/plot_wake.py).
#include <atomic>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>

#include "commands.hpp"
#include "ship_lrm/flight/parameters.hpp"
#include "ship_lrm/wake/probe_points.hpp"
#include "ship_lrm/wake/wake_precompute.hpp"

namespace ship_lrm::tools {
namespace fs = std::filesystem;
namespace {

std::atomic<bool> g_stop{false};
extern "C" void on_signal(int) { g_stop = true; }

}  // namespace

std::function<int()> add_wake_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("wake", "Precompute a ship air wake into a wake table (HDF5 + XDMF), with centre-plane statistics");
  auto opt = std::make_shared<wake::PrecomputeOptions>();
  auto preset = std::make_shared<std::string>();
  auto backend = std::make_shared<std::string>("auto");
  auto mesh = std::make_shared<std::string>();
  auto collision = std::make_shared<std::string>("bgk");
  auto flags = std::make_shared<std::array<bool, 4>>();  // overwrite, no-resume, float32, no-plot
  auto fine_box = std::make_shared<std::vector<double>>();
  auto fine_stored = std::make_shared<std::vector<double>>();
  auto probes = std::make_shared<std::string>();
  auto probe_frame = std::make_shared<std::string>("tunnel");
  auto probe_scale = std::make_shared<std::string>();
  cmd->add_option("--preset", *preset,
                  "default (the approach scenario's table, laminar over the deck; minutes), realistic (the same with the deck region "
                  "at 364 cells per ship length, turbulent; about 40 minutes on 2 cores) or tiny (tests); default and realistic are "
                  "cached under ~/.cache/ship_lrm when --out is not given");
  cmd->add_option("--ship", opt->ship, "natogd, sfs2 or FILE.stl (full scale, metres, ship frame: x forward, z down)");
  cmd->add_option("--scale", opt->scale, "model (1/50, the NRC wind-tunnel model) or full");
  cmd->add_option("--N", opt->domain.cells_per_length, "cells per ship length (thesis: converged at 364)");
  cmd->add_option("--motion", opt->motion, "static, pitch, heave, approach or FILE.csv (time_s,heave_m,roll_deg,pitch_deg)");
  cmd->add_option("--wind", opt->domain.wind, "wind over the deck from ahead, m/s (model case 9.77, approach 20.58)");
  cmd->add_option("--startup", opt->startup, "start-up before the first frame, s (default: the wind's time across the domain)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--duration", opt->duration, "seconds of frames");
  cmd->add_option("--interval", opt->frame_interval, "seconds between frames (thesis: 0.02)");
  cmd->add_option("--stats-interval", opt->stats_interval, "seconds between centre-plane samples (default: the frame interval)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--fine-ratio", opt->domain.fine.ratio,
                  "a fine region nested in the wake domain at this many fine cells per coarse cell (1 .. 16; 0: none; e.g. --N 52 "
                  "--fine-ratio 7: 364 cells per ship length over the deck, the thesis' converged resolution)")
      ->check(CLI::Range(0, 16));
  cmd->add_option("--fine-box", *fine_box,
                  "the fine region, ship lengths: AFT,FORE,HALF_WIDTH,TOP (x forward from the hangar door, |y|, height above the "
                  "waterline; default -0.42,0.35,0.15,0.3)")
      ->delimiter(',')
      ->expected(4);
  cmd->add_option("--fine-start", opt->domain.fine.start,
                  "start the fine region this many seconds into the run, from the coarse air (default 0; before it only the coarse "
                  "domain runs: give the start-up minus a few of the region's flow-through times)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--fine-stored", *fine_stored,
                  "the part of the fine region the table stores, ship lengths: AFT,FORE,TOP (as --fine-box; default: all of it)")
      ->delimiter(',')
      ->expected(3);
  cmd->add_option("--probes", *probes, "probe points, a CSV of x,y,z in metres: velocity series and statistics (FILE_probes*.csv)");
  cmd->add_flag("--probes-on-ship", opt->probes_on_ship,
                "probes fixed to the moving ship (as a model's probes in a wind tunnel): the air relative to them in the ship's axes "
                "(default: fixed points of the mean frame)");
  cmd->add_option("--probe-frame", *probe_frame,
                  "the probes' frame: tunnel (origin at the bottom of the hangar door on the centreline, x aft along the deck, y "
                  "starboard, z up; the NRC wind-tunnel frame of thesis 7.1) or ship (x forward, y starboard, z down)")
      ->check(CLI::IsMember({"tunnel", "ship"}));
  cmd->add_option("--probe-scale", *probe_scale, "the scale the probes are given at: model or full (default: the run's --scale)")
      ->check(CLI::IsMember({"model", "full"}));
  cmd->add_option("--backend", *backend, "cpu, cuda or auto");
  cmd->add_option("--smagorinsky", opt->domain.smagorinsky, "Smagorinsky constant s (thesis 6.2: 0.025)");
  cmd->add_option("--viscosity", opt->domain.viscosity, "kinematic viscosity, m^2/s (thesis tables 6.2, 6.3: 1.46072e-4)");
  cmd->add_option("--lattice-wind", opt->domain.lattice_wind,
                  "the wind in lattice units (default 0.045, Mach 0.078, the thesis' full-scale value; BGK is unstable from Mach 0.15)");
  cmd->add_option("--collision", *collision,
                  "bgk (the thesis') or recursive (recursive regularised, Coreixas et al. 2017: stable at the wake's tau to Mach 0.3)")
      ->check(CLI::IsMember({"bgk", "recursive"}));
  cmd->add_flag("--reflecting-inlet{false}", opt->domain.characteristic_inlet,
                "the thesis' velocity inlet, which reflects the waves from the ship (default: a characteristic inlet that lets them "
                "leave; with the reflecting one a disturbed stream grows, docs/design.md \"A characteristic inlet\")");
  cmd->add_flag("--no-slip-sea", opt->domain.no_slip_sea, "no-slip sea surface (the thesis) instead of slip");
  cmd->add_option("--out", opt->out, "wake table FILE.h5 (FILE.xdmf, FILE_centre_plane.csv/.png beside it)");
  cmd->add_option("--checkpoint-every", opt->checkpoint_seconds, "wall-clock seconds between checkpoints (FILE.h5.ckpt)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--mesh", *mesh, "also write the ship geometry as a binary STL (for rviz / ParaView)");
  cmd->add_flag("--overwrite", (*flags)[0], "replace an existing table (and --mesh file)");
  cmd->add_flag("--no-resume", (*flags)[1], "ignore a checkpoint (needs --overwrite when the table exists)");
  cmd->add_flag("--float32", (*flags)[2], "store float32 instead of float16");
  cmd->add_flag("--no-plot", (*flags)[3], "skip the PNG plots");
  return [=]() -> int {
    if (!cmd->parsed()) return -1;
    wake::PrecomputeOptions o = *opt;
    if (!preset->empty()) {
      // the preset's values, then whatever was given explicitly
      wake::PrecomputeOptions p = wake::preset(*preset);
      const auto given = [&](const char* name) { return cmd->count(name) > 0; };
      if (!given("--ship")) o.ship = p.ship;
      if (!given("--scale")) o.scale = p.scale;
      if (!given("--N")) o.domain.cells_per_length = p.domain.cells_per_length;
      if (!given("--motion")) o.motion = p.motion;
      if (!given("--wind")) o.domain.wind = p.domain.wind;
      if (!given("--startup")) o.startup = p.startup;
      if (!given("--duration")) o.duration = p.duration;
      if (!given("--interval")) o.frame_interval = p.frame_interval;
      o.half_precision = p.half_precision;
      // the preset's fine region, unless one is given; its start keeps its lead on a start-up given
      if (!given("--fine-ratio")) {
        const double lead = p.startup - p.domain.fine.start;
        o.domain.fine = p.domain.fine;
        if (given("--startup") && !given("--fine-start")) o.domain.fine.start = std::max(0.0, o.startup - lead);
        if (given("--fine-start")) o.domain.fine.start = opt->domain.fine.start;
      }
      if (o.out.empty() && (*preset == "default" || *preset == "realistic")) o.out = wake::preset_table_path(*preset);
    }
    if (o.out.empty()) throw CLI::ValidationError("--out", "give the table file (FILE.h5)");
    if (!fine_box->empty()) {
      if (o.domain.fine.ratio == 0) throw CLI::ValidationError("--fine-box", "needs --fine-ratio");
      o.domain.fine.aft = (*fine_box)[0];
      o.domain.fine.fore = (*fine_box)[1];
      o.domain.fine.half_width = (*fine_box)[2];
      o.domain.fine.top = (*fine_box)[3];
    }
    if (!fine_stored->empty()) {
      if (o.domain.fine.ratio == 0) throw CLI::ValidationError("--fine-stored", "needs --fine-ratio");
      o.domain.fine.stored_aft = (*fine_stored)[0];
      o.domain.fine.stored_fore = (*fine_stored)[1];
      o.domain.fine.stored_top = (*fine_stored)[2];
    }
    std::vector<std::array<double, 3>> probe_labels;
    if (!probes->empty()) {
      probe_labels = wake::read_probe_csv(*probes);
      const wake::ProbeFrame frame = wake::parse_probe_frame(*probe_frame);
      const double factor = wake::ship_scale(probe_scale->empty() ? o.scale : *probe_scale) / wake::ship_scale(o.scale);
      for (const auto& p : probe_labels) o.probes.push_back(wake::to_ship_frame(p, frame, factor));
    }
    o.domain.collision = lbm::parse_collision_model(*collision);
    // The flow over the superstructure reaches 1.11 times the wind; a faster lattice wind costs accuracy
    // (compressibility) and, with BGK, stability (docs/design.md, "A characteristic inlet"; benchmarks, 2026-12-04)
    if (const double mach = 1.15 * o.domain.lattice_wind * std::sqrt(3.0); mach > 0.15)
      std::fprintf(stderr,
                   "ship_lrm: warning: --lattice-wind %g puts the flow over the ship at lattice Mach %.2f: the mean flow moves by about "
                   "Mach^2 (3 %% of the wind at 0.1 against the default 0.045)%s\n",
                   o.domain.lattice_wind, mach,
                   o.domain.collision == lbm::CollisionModel::Bgk
                       ? ", and BGK's stream is unstable from about Mach 0.15 (`ship_lrm validate stream-stability`; --collision "
                         "recursive is not)"
                       : "");
    o.domain.density = o.scale == "model" ? 1.225 : 1.1934;  // thesis tables 6.2, 6.3
    o.domain.backend = lbm::parse_backend(*backend);
    if ((*flags)[2]) o.half_precision = false;
    check_output_file(o.out, "--out", true);  // a folder is refused here; an existing table below
    const std::string ckpt = o.out + ".ckpt";
    o.resume = !(*flags)[1];
    if (fs::exists(o.out) && !(o.resume && fs::exists(ckpt)) && !(*flags)[0]) {
      if ((*preset == "default" || *preset == "realistic") && o.out == wake::preset_table_path(*preset)) {
        // the cache is ours: reuse it when complete, else make it again
        const int expected = static_cast<int>(std::floor(o.duration / o.frame_interval + 1e-9)) + 1;
        int frames = 0;
        bool same = false;
        try {
          const wake::WakeTable t(o.out);
          frames = t.info().frames;
          same = t.info().motion == o.motion && t.info().scale == o.scale && std::abs(t.info().frame_interval - o.frame_interval) < 1e-12 &&
                 t.info().fine.ratio == o.domain.fine.ratio;
        } catch (const wake::TableError&) {
        }
        if (same && frames >= expected) {
          std::cout << "the " << *preset << " wake table is cached: " << o.out << "\n";
          return 0;
        }
        std::cout << "the cached " << *preset << " wake table " << o.out << " is incomplete or of another set-up (" << frames << " of "
                  << expected << " frames, no checkpoint): making it again\n";
        o.resume = false;
      } else {
        throw std::runtime_error(o.out + " exists; pass --overwrite to replace it");
      }
    }
    if (!(*flags)[1] && fs::exists(ckpt)) std::cout << "resuming from the checkpoint " << ckpt << "\n";
    // before the run; a run that resumes wrote its mesh the first time: the same command again must resume
    check_output_file(*mesh, "--mesh", (*flags)[0] || (o.resume && fs::exists(ckpt)));
    if (!mesh->empty()) {
      wake::write_stl(*mesh, wake::make_ship(o.ship, o.scale)->mesh(), "ship_lrm " + o.ship);
      std::cout << "wrote " << *mesh << "\n";
    }
    o.stop = &g_stop;
    ProgressLine bar("wake");
    o.progress = [&bar](const wake::PrecomputeOptions::Progress& p) {
      char detail[96];
      std::snprintf(detail, sizeof detail, "t = %7.2f s  %d frames  %6.1f MLUPS", p.sim_time, p.frames, p.mlups);
      bar.update(p.fraction, detail, p.eta_seconds);
    };
    std::signal(SIGINT, on_signal);
    std::signal(SIGTERM, on_signal);
    const wake::PrecomputeResult r = wake::precompute_wake(o);
    std::signal(SIGINT, SIG_DFL);
    std::signal(SIGTERM, SIG_DFL);
    bar.finish();
    std::cout << "ship " << o.ship << " (" << o.scale << "), motion " << o.motion << ", wind " << o.domain.wind
              << " m/s, N = " << o.domain.cells_per_length << ": " << r.cells << " cells, dx = " << r.dx << " m, dt = " << r.dt << " s\n"
              << r.steps << " steps (" << r.simulated << " s simulated) in " << r.wall_seconds << " s wall clock, " << r.mlups << " MLUPS, "
              << r.frames << " frames, " << r.rebuilds << " hull re-voxelisations, " << r.stats.samples << " centre-plane samples\n";
    if (r.interrupted) {
      std::cout << "stopped: checkpoint " << ckpt << " written; run the same command again to resume\n";
      return 130;
    }
    if (r.fine_cells > 0)
      std::cout << "fine region: " << r.fine_cells << " cells, dx = " << r.fine_dx << " m; MLUPS coarse " << r.coarse_mlups << ", fine "
                << r.fine_mlups << " (" << r.coarse_seconds << " s and " << r.fine_seconds << " s of steps)\n";
    std::cout << "wrote " << r.table << ", " << r.xdmf << ", " << r.centre_plane_csv << "\n";
    if (!r.fine_centre_plane_csv.empty()) std::cout << "wrote " << r.fine_centre_plane_csv << "\n";
    if (!r.probes_csv.empty()) {
      const std::string stats = fs::path(r.probes_csv).replace_extension("").string() + "_statistics.csv";
      wake::write_probe_statistics_csv(stats, r.probes, probe_labels, *probe_frame, o.domain.wind);
      std::cout << "wrote " << r.probes_csv << ", " << stats << "\n";
      if (!(*flags)[3] && !run_script("plot_probes.py", "'" + r.probes_csv + "' --wind " + std::to_string(o.domain.wind)))
        std::cerr << "ship_lrm: warning: the probe plots failed (needs python3 with scipy and matplotlib); the CSVs are complete\n";
    }
    if (!(*flags)[3]) {
      const fs::path png = fs::path(r.centre_plane_csv).replace_extension(".png");
      if (!run_script("plot_wake.py", "plane '" + r.centre_plane_csv + "' '" + png.string() + "'"))
        std::cerr << "ship_lrm: warning: plotting failed (needs python3 with matplotlib); the CSV " << r.centre_plane_csv
                  << " is complete\n";
      if (!r.fine_centre_plane_csv.empty()) {
        const fs::path fine_png = fs::path(r.fine_centre_plane_csv).replace_extension(".png");
        if (!run_script("plot_wake.py", "plane '" + r.fine_centre_plane_csv + "' '" + fine_png.string() + "'"))
          std::cerr << "ship_lrm: warning: plotting the fine centre plane failed; the CSV " << r.fine_centre_plane_csv << " is complete\n";
      }
    }
    return 0;
  };
}

}  // namespace ship_lrm::tools
