// `ship_lrm validate nrc-deck`: the NRC wind-tunnel deck case with a fine deck region (nrc_deck.hpp),
// its result as one JSON object (stdout and OUT/nrc_deck.json).
#include <algorithm>
#include <atomic>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <vector>

#include "commands.hpp"
#include "ship_lrm/wake/nrc_deck.hpp"
#include "ship_lrm/wake/probe_points.hpp"

namespace ship_lrm::tools {
namespace {

std::atomic<bool> g_nrc_stop{false};
extern "C" void on_nrc_signal(int) { g_nrc_stop = true; }

// NaN (a probe that never saw fluid) as JSON null
nlohmann::json number(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

nlohmann::json nrc_deck_json(const wake::NrcDeckResult& r) {
  nlohmann::json j;
  j["motion"] = r.options.motion;
  j["cells_per_length"] = r.options.cells_per_length;
  j["coarse_cells_per_length"] = r.coarse_cells_per_length;
  j["ratio"] = r.ratio;
  j["statistics_s"] = r.statistics_seconds;
  j["sample_interval_s"] = r.options.sample_interval;
  j["wind_m_s"] = r.wind;
  j["quick"] = r.options.quick;
  j["fine_box"] = {{"aft", r.run_box[0]}, {"fore", r.run_box[1]}, {"half_width", r.run_box[2]}, {"top", r.run_box[3]}};
  j["frame"] = "wind tunnel (thesis 7.1): origin at the bottom of the hangar door on the centreline, x aft, y starboard, z up; model scale";
  j["probes"] = nlohmann::json::array();
  for (const auto& p : r.probes) {
    nlohmann::json q;
    q["x"] = p.position[0];
    q["y"] = p.position[1];
    q["z"] = p.position[2];
    q["samples"] = p.samples;
    q["mean"] = {number(p.mean[0]), number(p.mean[1]), number(p.mean[2])};
    q["variance"] = {number(p.variance[0]), number(p.variance[1]), number(p.variance[2])};
    q["tke_over_u2"] = number(p.tke_over_u2);
    q["tke_over_u2_standard_error"] = number(p.tke_uncertainty);
    j["probes"].push_back(q);
  }
  j["deck_region"] = {{"tke_over_u2", number(r.deck_tke_over_u2)},
                      {"points", r.deck_points},
                      {"reversed_points", r.reversed_points},
                      {"reversed_max_u_over_U", r.reversed_max_over_u}};
  j["cost"] = {{"wall_s", r.run.wall_seconds},   {"coarse_cells", r.run.cells},
               {"fine_cells", r.run.fine_cells}, {"coarse_mlups", r.run.coarse_mlups},
               {"fine_mlups", r.run.fine_mlups}, {"mlups", r.run.mlups},
               {"steps", r.run.steps},           {"simulated_s", r.run.simulated}};
  j["table"] = r.run.table;
  j["fine_centre_plane_csv"] = r.run.fine_centre_plane_csv;
  j["centre_plane_csv"] = r.run.centre_plane_csv;
  j["probes_csv"] = r.run.probes_csv;
  return j;
}

}  // namespace

std::function<int()> add_nrc_deck_command(CLI::App& validate) {
  auto* cmd = validate.add_subcommand(
      "nrc-deck",
      "The NRC wind-tunnel deck case (thesis 7.1, 7.2: 1/50 NatoGD, 9.77 m/s; static, pitch 5 deg at 1 Hz or heave 0.04 m at 1 Hz) "
      "with a fine deck region: statistics at the thesis' two deck probes and over the deck, as one JSON object");
  struct Opts {
    wake::NrcDeckOptions run;
    std::string probes, backend = "auto", out;
    std::vector<double> box;
    bool json = false, overwrite = false;
  };
  auto o = std::make_shared<Opts>();
  cmd->add_option("--motion", o->run.motion, "static, pitch or heave")
      ->check(CLI::IsMember({"static", "pitch", "heave"}))
      ->capture_default_str();
  cmd->add_option("--cells-per-length", o->run.cells_per_length,
                  "cells per ship length in the fine region (364: the thesis' converged setting; 546 as an option)")
      ->check(CLI::Range(24, 2048))
      ->capture_default_str();
  cmd->add_option("--seconds", o->run.seconds, "seconds of statistics after the start-up")
      ->check(CLI::Range(1e-3, 1e4))
      ->capture_default_str();
  cmd->add_option("--sample-interval", o->run.sample_interval, "seconds between samples of the probes and centre planes")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  cmd->add_option("--startup", o->run.startup, "start-up before the statistics, s (default: the wind's time across the wake domain)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_flag("--quick", o->run.quick, "the CI variant: 64 cells per length, 0.3 s of statistics (laminar: checks the pipeline)");
  cmd->add_option("--fine-box", o->box,
                  "the fine region, ship lengths: AFT,FORE,HALF_WIDTH,TOP (default -0.3,0.8,0.13,0.31: the whole superstructure; a moving "
                  "ship's fore face goes "
                  "past the bow)")
      ->delimiter(',')
      ->expected(4);
  cmd->add_option("--probes", o->probes, "more probes after the thesis' two: a CSV of x,y,z (m, wind-tunnel frame, model scale)");
  cmd->add_option("--backend", o->backend, "cpu, cuda or auto")->check(CLI::IsMember({"cpu", "cuda", "auto"}))->capture_default_str();
  cmd->add_option("--out", o->out, "folder for the table, the CSVs and nrc_deck.json (default nrc-deck-MOTION-NCELLS)");
  cmd->add_flag("--overwrite", o->overwrite, "replace an earlier run's table in --out");
  cmd->add_flag("--json", o->json, "print only the JSON object on stdout (progress on stderr)");
  return [o, cmd]() -> int {
    if (!cmd->parsed()) return -1;
    wake::NrcDeckOptions run = wake::with_quick_setting(o->run);
    wake::nest_resolution(run.cells_per_length);  // ConfigError before anything is written
    run.backend = lbm::parse_backend(o->backend);
    if (!o->box.empty()) std::copy(o->box.begin(), o->box.end(), run.box.begin());
    if (!o->probes.empty()) run.extra_probes = wake::read_probe_csv(o->probes);
    run.out_dir = o->out.empty() ? "nrc-deck-" + run.motion + "-" + std::to_string(run.cells_per_length) : o->out;
    const std::filesystem::path table =
        std::filesystem::path(run.out_dir) / ("nrc_deck_" + run.motion + "_N" + std::to_string(run.cells_per_length) + ".h5");
    const bool checkpoint = std::filesystem::exists(table.string() + ".ckpt");
    if (std::filesystem::exists(table) && !checkpoint && !o->overwrite)
      throw std::runtime_error(table.string() + " exists (an earlier run); pass --overwrite to replace it or choose another --out");
    if (o->overwrite && !checkpoint) run.resume = false;
    std::ostream& log = o->json ? std::cerr : std::cout;
    const auto nest = wake::nest_resolution(run.cells_per_length);
    log << "nrc-deck: " << run.motion << ", " << run.cells_per_length << " cells per ship length over the deck (" << nest[0] << " x "
        << nest[1] << "), " << run.seconds << " s of statistics; writing into " << run.out_dir << "\n";
    ProgressLine bar("nrc-deck");
    run.progress = [&bar](const wake::PrecomputeOptions::Progress& p) {
      char detail[96];
      std::snprintf(detail, sizeof detail, "t = %6.3f s  %6.1f MLUPS", p.sim_time, p.mlups);
      bar.update(p.fraction, detail, p.eta_seconds);
    };
    run.stop = &g_nrc_stop;
    std::signal(SIGINT, on_nrc_signal);
    std::signal(SIGTERM, on_nrc_signal);
    const wake::NrcDeckResult r = wake::run_nrc_deck(run);
    std::signal(SIGINT, SIG_DFL);
    std::signal(SIGTERM, SIG_DFL);
    bar.finish();
    if (r.run.interrupted) {
      log << "stopped: checkpoint " << r.run.table << ".ckpt written; run the same command again to resume\n";
      return 130;
    }
    const nlohmann::json j = nrc_deck_json(r);
    const std::string json_path = (std::filesystem::path(run.out_dir) / "nrc_deck.json").string();
    std::ofstream out(json_path);
    out << j.dump(2) << "\n";
    if (!out) throw std::runtime_error("cannot write " + json_path);
    if (o->json) {
      std::cout << j.dump() << "\n";
    } else {
      std::cout << j.dump(2) << "\nwrote " << json_path << "\n";
    }
    return 0;
  };
}

}  // namespace ship_lrm::tools
