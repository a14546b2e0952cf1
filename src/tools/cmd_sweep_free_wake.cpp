// `ship_lrm sweep free-wake`: the mean induced velocity of the uniformly loaded actuator disk from a
// free vortex-ring wake (rotor/free_wake_disk.hpp) over edgewise speeds, beside Glauert's formula: an
// independent reference for `sweep inflow` (CSV + PNG).
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "commands.hpp"
#include "ship_lrm/lrm/domain.hpp"
#include "ship_lrm/rotor/free_wake_disk.hpp"
#include "ship_lrm/rotor/momentum_theory.hpp"

namespace ship_lrm::tools {
namespace fs = std::filesystem;

std::function<int()> add_free_wake_sweep(CLI::App& sweep) {
  auto* cmd = sweep.add_subcommand("free-wake",
                                   "Uniformly loaded actuator disk at zero incidence with a free vortex-ring wake: its mean induced "
                                   "velocity over speed beside Glauert's (an independent reference for `sweep inflow`)");
  struct Opts {
    std::string speeds = "10,20,30,40";
    double thrust = 24525, spacing = 0.03, length = 8, merge = 2, core = 0.03, settle = 1.5, average = 1.5, climb = 0;
    int ring_points = 48;
    std::string out, lrm;
    bool overwrite = false, no_plot = false;
  };
  auto o = std::make_shared<Opts>();
  cmd->add_option("--speeds", o->speeds, "edgewise speeds in m/s: start:step:stop or a comma list")->capture_default_str();
  cmd->add_option("--climb", o->climb, "axial climb rate in m/s for every case (as `sweep inflow --climb`)")
      ->check(CLI::Range(0.0, 200.0))
      ->capture_default_str();
  cmd->add_option("--thrust", o->thrust, "N, uniform over the disk (radius and density: the LRM's)")
      ->check(CLI::Range(1.0, 1e6))
      ->capture_default_str();
  cmd->add_option("--spacing", o->spacing, "rings this many R apart along the wake")->check(CLI::Range(0.005, 0.5))->capture_default_str();
  cmd->add_option("--wake-length", o->length, "the wake cut this many R behind the disk")
      ->check(CLI::Range(1.0, 100.0))
      ->capture_default_str();
  cmd->add_option("--merge-length", o->merge, "rings merge pairwise from this many R on (doubling each time)")
      ->check(CLI::Range(0.1, 100.0))
      ->capture_default_str();
  cmd->add_option("--core", o->core, "the wake segments' core, R (free_wake_disk.hpp)")
      ->check(CLI::Range(0.001, 0.5))
      ->capture_default_str();
  cmd->add_option("--ring-points", o->ring_points, "nodes per ring")->check(CLI::Range(8, 4096))->capture_default_str();
  cmd->add_option("--settle", o->settle, "R / v_h after the wake has reached its length, before averaging")
      ->check(CLI::Range(0.0, 50.0))
      ->capture_default_str();
  cmd->add_option("--average", o->average, "R / v_h averaged")->check(CLI::Range(0.01, 50.0))->capture_default_str();
  cmd->add_option("--out", o->out, "output directory (free_wake_sweep.csv, .png)")->required();
  cmd->add_option("--lrm", o->lrm, "an inflow_sweep.csv of `sweep inflow` to plot beside")->check(CLI::ExistingFile);
  cmd->add_flag("--overwrite", o->overwrite, "replace existing output files");
  cmd->add_flag("--no-plot", o->no_plot, "CSV only");
  return [o, cmd]() -> int {
    if (!cmd->parsed()) return -1;
    const auto speeds = parse_speeds(o->speeds);
    if (!o->lrm.empty()) {
      check_csv_columns(o->lrm, "--lrm", {"N", "reach", "speed_m_s", "lrm_mean_m_s", "momentum_theory_m_s"});
      // the LRM's sweep must have flown the same climb (a sweep from before --climb had none)
      std::ostringstream ours;
      ours << o->climb;
      for (const std::string& text : csv_column(o->lrm, "--lrm", "climb_m_s").value_or(std::vector<std::string>{"0"})) {
        char* end = nullptr;
        const double climb = std::strtod(text.c_str(), &end);
        if (end == text.c_str() || !(std::abs(climb - o->climb) <= 1e-6 * std::max(1.0, o->climb)))
          throw CLI::ValidationError("--lrm", "'" + o->lrm + "' was swept at a climb of " + text + " m/s, this sweep at " + ours.str() +
                                                  " m/s (--climb): the two would not be comparable");
      }
    }
    const lrm::LrmConfig lrm_defaults;
    std::vector<rotor::FreeWakeDiskConfig> cases;
    for (double v : speeds) {  // every case checked before any run
      rotor::FreeWakeDiskConfig c;
      c.radius = lrm_defaults.radius, c.density = lrm_defaults.density, c.thrust = o->thrust;
      c.air = Vec3(-v, 0, o->climb);
      c.ring_points = o->ring_points, c.core = o->core, c.settle = o->settle, c.average = o->average;
      rotor::set_wake_lengths(c, o->spacing, o->length, o->merge);
      if (c.wake_age / c.step > 20000 || c.step > 0.2)
        throw CLI::ValidationError("--spacing", "gives a step of " + std::to_string(c.step) + " R / v_h and " +
                                                    std::to_string(static_cast<long>(c.wake_age / c.step)) + " rings at " +
                                                    std::to_string(v) + " m/s (at most 0.2 and 20000)");
      cases.push_back(c);
    }
    const fs::path dir(o->out);
    prepare_output(dir, {"free_wake_sweep.csv", "free_wake_sweep.png"}, o->overwrite);
    std::ofstream csv(dir / "free_wake_sweep.csv");
    csv << "speed_m_s,free_wake_mean_m_s,free_wake_min_m_s,free_wake_max_m_s,momentum_theory_m_s,hover_momentum_theory_m_s,"
           "mean_over_momentum_theory,ring_points,spacing_R,wake_length_R,merge_length_R,core_R,rings,steps,wall_s,climb_m_s\n";
    for (std::size_t k = 0; k < cases.size(); ++k) {
      const auto start = std::chrono::steady_clock::now();
      const std::string label = case_label(speeds[k], 0, o->climb);
      ProgressLine bar(label);
      cases[k].progress = [&bar](double fraction, double mean) {
        std::ostringstream now;
        now << std::fixed << std::setprecision(3) << "mean " << mean << " m/s";
        bar.update(fraction, now.str());
      };
      const auto r = rotor::solve_free_wake_disk(cases[k]);
      bar.finish();
      const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      std::cout << std::fixed << std::setprecision(3) << label << ": free wake " << r.mean << " m/s (" << r.min << " - " << r.max
                << "), momentum theory " << r.momentum << ", ratio " << std::setprecision(4) << r.mean / r.momentum << "; " << r.rings
                << " rings, " << r.steps << " steps in " << std::setprecision(1) << wall << " s" << std::endl;
      csv << std::setprecision(6) << speeds[k] << "," << r.mean << "," << r.min << "," << r.max << "," << r.momentum << "," << r.hover
          << "," << r.mean / r.momentum << "," << o->ring_points << "," << o->spacing << "," << o->length << "," << o->merge << ","
          << o->core << "," << r.rings << "," << r.steps << "," << wall << "," << o->climb << "\n";
      csv.flush();
    }
    csv.close();
    std::cout << "wrote " << (dir / "free_wake_sweep.csv").string() << "\n";
    if (!o->no_plot) plot("sweep_free_wake", dir / "free_wake_sweep.csv", dir / "free_wake_sweep.png", o->lrm);
    return 0;
  };
}

}  // namespace ship_lrm::tools
