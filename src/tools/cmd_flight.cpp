// `ship_lrm trim` and `ship_lrm doublet`: Bo 105 flight-model sweeps, written as CSV (header row) and
// plotted to PNG by scripts/plot_flight.py.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "commands.hpp"
#include "lrm_face_options.hpp"
#include "ship_lrm/flight/doublet.hpp"
#include "ship_lrm/flight/trim.hpp"
#include "ship_lrm/lrm/lrm_inflow.hpp"

namespace ship_lrm::tools {
namespace fs = std::filesystem;
using namespace ship_lrm::flight;

namespace {
constexpr double kDeg = 180.0 / M_PI;
}  // namespace

namespace {
HelicopterParameters load_config(const std::string& path) { return path.empty() ? load_default_bo105() : load_helicopter_parameters(path); }
}  // namespace

std::function<int()> add_trim_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("trim", "Trim the Bo 105 in steady level flight over a range of speeds (thesis figs. 8.5-8.7)");
  struct Opts {
    std::string speeds = "0:5:70", inflow = "pitt_peters", out, config, reference, backend = "auto";
    int nodes = 64;
    double reach = 1.25, warm_up = 3.0;
    bool overwrite = false, no_plot = false;
    LrmFaceOptions face;
  };
  auto o = std::make_shared<Opts>();
  cmd->add_option("--speeds", o->speeds, "speeds in m/s: start:step:stop or a comma list")->capture_default_str();
  cmd->add_option("--inflow", o->inflow, "inflow model: pitt_peters, or lrm (the LRM fluid domain, thesis 8.2.1)")
      ->check(CLI::IsMember({"pitt_peters", "lrm"}))
      ->capture_default_str();
  cmd->add_option("--N", o->nodes, "lrm: lattice nodes per 4R")->check(CLI::Range(16, 512))->capture_default_str();
  cmd->add_option("--reach", o->reach, "lrm: domain edge / 4R (a >= 1)")->check(CLI::Range(1.0, 8.0))->capture_default_str();
  cmd->add_option("--backend", o->backend, "lrm: cpu, cuda or auto")->check(CLI::IsMember({"cpu", "cuda", "auto"}))->capture_default_str();
  cmd->add_option("--warm-up", o->warm_up, "lrm: s simulated before the first trim evaluation")
      ->check(CLI::Range(0.0, 600.0))
      ->capture_default_str();
  o->face.add_to(*cmd);  // lrm: the domain's faces, as in `sweep inflow`
  cmd->add_option("--out", o->out, "output directory (trim.csv, trim.png)")->required();
  cmd->add_option("--config", o->config, "helicopter parameter file (default: the shipped config/bo105.yaml)");
  cmd->add_option("--reference", o->reference, "CSV of measured trim data with the same column names, plotted as points");
  cmd->add_flag("--overwrite", o->overwrite, "replace existing output files");
  cmd->add_flag("--no-plot", o->no_plot, "write the CSV only");
  return [o, cmd]() -> int {
    if (!cmd->parsed()) return -1;
    if (o->inflow != "lrm") refuse_lrm_options(*cmd, {"--N", "--reach", "--backend", "--warm-up"});
    const auto speeds = parse_speeds(o->speeds);
    const HelicopterParameters p = load_config(o->config);
    if (!o->reference.empty()) check_csv_columns(o->reference, "--reference", {"speed_m_s"});
    const fs::path dir(o->out);
    prepare_output(dir, {"trim.csv", "trim.png"}, o->overwrite);
    std::unique_ptr<rotor::InflowModel> inflow;
    if (o->inflow == "lrm") {
      lrm::LrmConfig c;
      c.nodes = o->nodes;
      c.reach = o->reach;
      c.backend = lbm::parse_backend(o->backend);
      c.radius = p.main_rotor.radius;
      c.density = p.density;
      o->face.apply(c);
      inflow = std::make_unique<lrm::LrmInflow>(lrm::config_for_stream(c, *std::max_element(speeds.begin(), speeds.end())), o->warm_up);
    }
    Helicopter heli(p, std::move(inflow));
    std::ofstream csv(dir / "trim.csv");
    const bool lrm = o->inflow == "lrm";
    csv << "speed_m_s,converged,residual,iterations,total_power_kW,main_power_kW,tail_power_kW,collective_pct,longitudinal_pct,"
           "lateral_pct,pedal_pct,collective_deg,forward_cyclic_deg,right_cyclic_deg,tail_pitch_deg,pitch_deg,roll_deg,thrust_N,"
           "induced_velocity_m_s,coning_deg,disk_tilt_forward_deg,disk_tilt_right_deg";
    if (lrm)
      csv << ",pp_converged,pp_total_power_kW,pp_collective_pct,pp_longitudinal_pct,pp_lateral_pct,pp_pedal_pct,pp_pitch_deg,pp_roll_deg,"
             "lrm_faces";
    csv << "\n";
    TrimOptions opt, pp_opt;
    double speed = 0;  // the speed being trimmed, for the progress lines
    const auto wall_start = std::chrono::steady_clock::now();
    const auto progress = [&](int iteration, double residual) {
      const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
      std::cout << "  LRM trim at " << speed << " m/s: iteration " << iteration << ", residual " << residual << " (tolerance "
                << opt.tolerance << "), " << std::lround(wall) << " s so far\n"
                << std::flush;
    };
    // With the LRM, each speed starts from the Pitt-Peters trim at that speed (thesis 8.5: the coupled
    // trim beside Pitt-Peters): a cold start or the previous speed's LRM trim is often too far off for
    // Newton on a flow that is only statistically steady, and the comparison is written alongside.
    Helicopter pp_heli(p);
    int failed = 0;
    for (double v : speeds) {
      TrimTarget t;
      t.speed = v;
      TrimResult pp;
      if (lrm) {
        pp = trim(pp_heli, t, pp_opt);
        std::cout << "Pitt-Peters: " << pp.message << "\n";
        if (pp.converged) {
          pp_opt.initial_controls = pp.controls;
          pp_opt.initial_attitude = Vec3(pp.roll, pp.pitch, 0);
          opt = pp_opt;
        }
      }
      speed = v;
      opt.progress = lrm ? std::function<void(int, double)>(progress) : nullptr;  // (Pitt-Peters trims in well under a second)
      const TrimResult r = trim(heli, t, opt);
      std::cout << r.message << "\n";
      if (r.converged && !lrm) {
        opt.initial_controls = r.controls;
        opt.initial_attitude = Vec3(r.roll, r.pitch, 0);
      }
      if (!r.converged) ++failed;
      csv << std::setprecision(6) << v << "," << (r.converged ? 1 : 0) << "," << r.residual << "," << r.iterations << ","
          << r.total_power / 1e3 << "," << r.main_power / 1e3 << "," << r.tail_power / 1e3 << "," << r.controls.collective << ","
          << r.controls.longitudinal << "," << r.controls.lateral << "," << r.controls.pedal << "," << r.angles.main.collective * kDeg
          << "," << r.angles.main.forward * kDeg << "," << r.angles.main.right * kDeg << "," << r.angles.tail * kDeg << ","
          << r.pitch * kDeg << "," << r.roll * kDeg << "," << r.thrust << "," << r.induced_velocity << "," << r.flapping.x() * kDeg << ","
          << r.flapping.y() * kDeg << "," << r.flapping.z() * kDeg;
      if (lrm)
        csv << "," << (pp.converged ? 1 : 0) << "," << pp.total_power / 1e3 << "," << pp.controls.collective << ","
            << pp.controls.longitudinal << "," << pp.controls.lateral << "," << pp.controls.pedal << "," << pp.pitch * kDeg << ","
            << pp.roll * kDeg << "," << o->face.label();
      csv << "\n";
    }
    csv.close();
    std::cout << "wrote " << (dir / "trim.csv").string() << "\n";
    if (!o->no_plot) plot("trim", dir / "trim.csv", dir / "trim.png", o->reference);
    if (failed) {
      std::cerr << "ship_lrm: trim did not converge at " << failed << " of " << speeds.size()
                << " speeds (converged = 0 in the CSV, with the residual)\n";
      return 4;
    }
    return 0;
  };
}

std::function<int()> add_doublet_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("doublet", "Doublet input from trimmed flight (thesis fig. 8.8 and appendix VI)");
  struct Opts {
    std::string axis = "lateral", out, config, engine = "governed";
    double speed = 13.37, amplitude = 10, start = 1, pulse = 1, duration = 8;
    bool overwrite = false, no_plot = false;
  };
  auto o = std::make_shared<Opts>();
  cmd->add_option("--axis", o->axis, "control moved: lateral, longitudinal, collective or pedal")
      ->check(CLI::IsMember({"lateral", "longitudinal", "collective", "pedal"}))
      ->capture_default_str();
  auto* speed_opt = cmd->add_option("--speed", o->speed,
                                    "trimmed speed, m/s (default: the thesis' flight-test speed for the axis: lateral 13.37, "
                                    "longitudinal 12.86, collective 7.72, pedal 13.37)")
                        ->check(CLI::Range(0.0, 90.0));
  cmd->add_option("--amplitude", o->amplitude, "% of control travel")->check(CLI::Range(0.1, 50.0))->capture_default_str();
  cmd->add_option("--start", o->start, "s of trimmed flight before the doublet")->check(CLI::Range(0.0, 60.0))->capture_default_str();
  cmd->add_option("--pulse", o->pulse, "s, length of each half of the doublet")->check(CLI::Range(0.01, 20.0))->capture_default_str();
  cmd->add_option("--duration", o->duration, "s simulated")->check(CLI::Range(0.1, 600.0))->capture_default_str();
  cmd->add_option("--engine", o->engine, "governed (rotor speed can droop) or constant (rotor speed held)")
      ->check(CLI::IsMember({"governed", "constant"}))
      ->capture_default_str();
  cmd->add_option("--out", o->out, "output directory (doublet_<axis>.csv, .png)")->required();
  cmd->add_option("--config", o->config, "helicopter parameter file (default: the shipped config/bo105.yaml)");
  cmd->add_flag("--overwrite", o->overwrite, "replace existing output files");
  cmd->add_flag("--no-plot", o->no_plot, "write the CSV only");
  return [o, cmd, speed_opt]() -> int {
    if (!cmd->parsed()) return -1;
    if (speed_opt->count() == 0)  // thesis 8.2.2 (fig. 8.8) and appendix VI (figs. X, XI)
      o->speed = o->axis == "longitudinal" ? 12.86 : o->axis == "collective" ? 7.72 : 13.37;
    if (o->duration <= o->start) throw CLI::ValidationError("--duration", "must be longer than --start");
    const HelicopterParameters p = load_config(o->config);
    DoubletOptions d;
    d.axis = parse_control_axis(o->axis);
    d.speed = o->speed;
    d.amplitude = o->amplitude;
    d.start = o->start;
    d.pulse = o->pulse;
    d.duration = o->duration;
    d.engine = o->engine == "governed" ? EngineMode::Governed : EngineMode::ConstantSpeed;
    const fs::path dir(o->out);
    const std::string base = "doublet_" + o->axis;
    prepare_output(dir, {base + ".csv", base + ".png"}, o->overwrite);
    const DoubletResult r = run_doublet(p, d);
    std::cout << r.trim.message << "\n";
    std::ofstream csv(dir / (base + ".csv"));
    csv << "time_s,collective_pct,longitudinal_pct,lateral_pct,pedal_pct,p_deg_s,q_deg_s,r_deg_s,roll_deg,pitch_deg,yaw_deg,"
           "rate_of_descent_m_s,rotor_speed_ratio,main_power_kW,engine_power_kW\n";
    for (const auto& s : r.samples)
      csv << std::setprecision(6) << s.time << "," << s.controls.collective << "," << s.controls.longitudinal << "," << s.controls.lateral
          << "," << s.controls.pedal << "," << s.rates.x() * kDeg << "," << s.rates.y() * kDeg << "," << s.rates.z() * kDeg << ","
          << s.attitude.x() * kDeg << "," << s.attitude.y() * kDeg << "," << s.attitude.z() * kDeg << "," << s.rate_of_descent << ","
          << s.rotor_speed_ratio << "," << s.main_power / 1e3 << "," << s.engine_power / 1e3 << "\n";
    csv.close();
    std::cout << "wrote " << (dir / (base + ".csv")).string() << "\n";
    if (!o->no_plot) plot("doublet", dir / (base + ".csv"), dir / (base + ".png"), "");
    return 0;
  };
}

}  // namespace ship_lrm::tools
