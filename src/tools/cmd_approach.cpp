// `ship_lrm approach`: the ship approach of thesis 9.1 in simulated time, ROS-free (lrm/approach.hpp).
// Writes approach.csv (one row per output interval) and, through scripts/analyze_approach.py, the time
// series of Delta C_T, C_Mx, C_My and their wavelet amplitudes (thesis figs. 9.4, 9.5) with a summary.
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <optional>

#include "commands.hpp"
#include "lrm_face_options.hpp"
#include "ship_lrm/flight/parameters.hpp"
#include "ship_lrm/lrm/approach.hpp"
#include "ship_lrm/lrm/deadline_watch.hpp"
#include "ship_lrm/lrm/domain_slice.hpp"
#include "ship_lrm/lrm/realtime_inflow.hpp"
#include "ship_lrm/lrm/wall_clock_pacer.hpp"
#include "ship_lrm/wake/wake_precompute.hpp"

namespace ship_lrm::tools {
namespace fs = std::filesystem;

namespace {
constexpr double kPlaneSampleInterval = 0.02;  // s between samples of --plane-mean-from

void write_header(std::ostream& o) {
  o << "time_s,x_m,y_m,z_m,distance_to_spot_m,height_above_deck_m,speed_m_s,thrust_N,CT,CMx,CMy,main_power_kW,inflow_x_m_s,"
       "inflow_y_m_s,inflow_z_m_s,ship_heave_m,ship_pitch_deg,lrm_wall_cells,lrm_voxelisations,face_refreshes\n";
}
void write_row(std::ostream& o, const lrm::ApproachSample& s) {
  o << std::setprecision(17) << s.time << ',' << s.cg.x() << ',' << s.cg.y() << ',' << s.cg.z() << ',' << s.distance << ','
    << s.height_above_deck << ',' << s.speed << ',' << s.thrust << ',' << s.ct << ',' << s.cmx << ',' << s.cmy << ','
    << s.main_power / 1000.0 << ',' << s.inflow_mean.x() << ',' << s.inflow_mean.y() << ',' << s.inflow_mean.z() << ',' << s.ship_heave
    << ',' << s.ship_pitch * 180.0 / M_PI << ',' << s.wall_cells << ',' << s.voxelisations << ',' << s.face_refreshes << '\n';
}
}  // namespace

std::function<int()> add_approach_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("approach",
                                 "Bo 105 approach onto the ship of a wake table, fixed controls along the path of thesis 9.1, "
                                 "LRM (or Pitt-Peters) inflow, in simulated time");
  struct Opts {
    lrm::ApproachConfig cfg;
    std::string out, config, backend = "auto";
    double output_interval = 0.01;
    bool overwrite = false, no_plot = false, no_ship = false, no_wake = false, no_fuselage = false;
    bool realtime = false, pipelined = false, no_rotor_forces = false;
    std::optional<double> plane_from;
    LrmFaceOptions faces;
  };
  auto o = std::make_shared<Opts>();
  o->cfg.lrm.nodes = 32;
  cmd->add_option("--wake", o->cfg.table,
                  "wake table (HDF5) of a full-scale ship, or default or realistic: the cached table of that preset (`ship_lrm wake "
                  "--preset NAME`); default: default");
  cmd->add_option("--inflow", o->cfg.inflow, "lrm, or pitt_peters (the table's air at the hub as the wind)")
      ->check(CLI::IsMember({"lrm", "pitt_peters"}))
      ->capture_default_str();
  cmd->add_option("--N", o->cfg.lrm.nodes, "lrm: lattice nodes per 4R")->check(CLI::Range(16, 512))->capture_default_str();
  cmd->add_option("--reach", o->cfg.lrm.reach, "lrm: domain edge / 4R (a >= 1)")->check(CLI::Range(1.0, 8.0))->capture_default_str();
  cmd->add_option("--backend", o->backend, "lrm: cpu, cuda or auto")->check(CLI::IsMember({"cpu", "cuda", "auto"}))->capture_default_str();
  cmd->add_option("--duration", o->cfg.duration, "s simulated (thesis 9.1: 30)")->capture_default_str();
  cmd->add_option("--startup", o->cfg.startup, "s of start-up; the Delta coefficients are taken against this time")->capture_default_str();
  cmd->add_option("--start-distance", o->cfg.path.start_distance, "m behind the landing spot at t = 0")->capture_default_str();
  cmd->add_option("--height", o->cfg.path.height, "m, cg above the deck")->capture_default_str();
  cmd->add_option("--lateral", o->cfg.path.lateral, "m, cg starboard of the centreline")->capture_default_str();
  cmd->add_option("--speed", o->cfg.path.speed, "m/s towards the bow, relative to the ship")->capture_default_str();
  cmd->add_option("--decelerate-at", o->cfg.path.decelerate_at, "s, start of the linear deceleration")->capture_default_str();
  cmd->add_option("--hover-at", o->cfg.path.hover_at, "s, hover from here")->capture_default_str();
  cmd->add_option("--trim-speed", o->cfg.trim_speed, "m/s airspeed of the fixed controls' trim (default: |wind| + speed)");
  cmd->add_option("--table-offset", o->cfg.table_offset, "s into the table at t = 0")->capture_default_str();
  cmd->add_option("--lattice-margin", o->cfg.lattice_margin,
                  "lrm: the lattice's reference speed (Mach 0.3) over |wind| + path speed; larger: a slower lattice stream, more steps")
      ->check(CLI::Range(1.0, 20.0))
      ->capture_default_str();
  cmd->add_flag("--no-ship", o->no_ship, "lrm: no ship or sea walls in the LRM domain");
  cmd->add_flag("--no-fuselage", o->no_fuselage, "lrm: no fuselage walls in the LRM domain");
  o->faces.add_to(*cmd);
  cmd->add_flag("--no-wake", o->no_wake, "the table's free stream instead of its wake (thesis appendix VIII)");
  cmd->add_option("--plane-mean-from", o->plane_from,
                  "lrm: from this time (s) to the end, average the x-z plane through the hub in the domain's frame (meant for a "
                  "hover) beside the table's air at the same points: centre_plane_mean.csv and .png (thesis fig. 9.3 (c))")
      ->check(CLI::Range(0.0, 1e6));
  cmd->add_flag("--no-rotor-forces", o->no_rotor_forces,
                "lrm: the rotor's forces stay off the fluid, so that the domain recomputes the ship's wake alone (to compare "
                "with the table; a diagnostic: the rotor has no induced flow of its own)");
  cmd->add_option("--output-interval", o->output_interval, "s between CSV rows")->check(CLI::Range(1e-4, 10.0))->capture_default_str();
  cmd->add_option("--out", o->out, "output directory (approach.csv, approach.png, approach_wavelets.png, approach_summary.csv)")
      ->required();
  cmd->add_option("--config", o->config, "helicopter parameter file (default: the shipped config/bo105.yaml)");
  cmd->add_flag("--overwrite", o->overwrite, "replace existing output files");
  cmd->add_flag("--no-plot", o->no_plot, "write the CSV only");
  cmd->add_flag("--realtime", o->realtime,
                "lrm: pace to the wall clock; the LRM runs in its own thread and a step whose inflow misses its deadline "
                "flies on Pitt-Peters (counted; not deterministic)");
  cmd->add_flag("--free-flight", o->cfg.free_flight,
                "held on the path during the start-up (which re-trims the controls for the inflow model), then flying freely "
                "(6-DOF) with those controls fixed (no pilot): the open-loop response; ends where the skids touch the ship or the sea");
  cmd->add_flag("--pipelined", o->pipelined,
                "with --realtime: the LRM " + std::to_string(lrm::kPipelineDepth) +
                    " LBM intervals behind the flight model (more time per LBM step)");
  return [o, cmd]() -> int {
    if (!cmd->parsed()) return -1;
    if (o->cfg.inflow != "lrm")
      refuse_lrm_options(*cmd, {"--N", "--reach", "--backend", "--no-ship", "--no-fuselage", "--plane-mean-from", "--no-rotor-forces"});
    if (o->plane_from && *o->plane_from >= o->cfg.duration)
      throw ConfigError("--plane-mean-from " + std::to_string(*o->plane_from) + " s lies beyond the run's end (--duration " +
                        std::to_string(o->cfg.duration) + " s): nothing to average");
    lrm::ApproachConfig cfg = o->cfg;
    cfg.lrm.backend = lbm::parse_backend(o->backend);
    cfg.ship_walls = !o->no_ship;
    cfg.wake = !o->no_wake;
    cfg.fuselage = !o->no_fuselage;
    cfg.rotor_forces_on_fluid = !o->no_rotor_forces;
    o->faces.apply(cfg.lrm);
    std::string preset;
    cfg.table = wake::named_table(cfg.table, preset);
    if (!fs::exists(cfg.table)) throw ConfigError(wake::missing_table_message(cfg.table, preset));
    if (o->pipelined && !o->realtime) throw ConfigError("--pipelined needs --realtime");
    if (o->plane_from && o->realtime)
      throw ConfigError("--plane-mean-from needs a run in simulated time (with --realtime the LRM's own thread owns the domain)");
    if (o->realtime && cfg.inflow != "lrm") throw ConfigError("--realtime needs --inflow lrm (Pitt-Peters has no deadlines to meet)");
    const fs::path dir(o->out);
    std::vector<std::string> outputs = {"approach.csv", "approach.png", "approach_wavelets.png", "approach_summary.csv"};
    if (o->plane_from) add_plane_outputs(outputs, "centre_plane_mean");
    prepare_output(dir, outputs, o->overwrite);
    const flight::HelicopterParameters p = o->config.empty() ? flight::load_default_bo105() : flight::load_helicopter_parameters(o->config);
    std::cout << "approach: trimming the Bo 105 (Pitt-Peters) for the fixed controls ...\n" << std::flush;
    std::optional<lrm::RealTimeMode> realtime;
    if (o->realtime) realtime = o->pipelined ? lrm::RealTimeMode::Pipelined : lrm::RealTimeMode::LockStep;
    lrm::ShipApproach run(cfg, p, nullptr, realtime);
    const auto& info = run.table_info();
    std::cout << "approach: ship " << info.ship << " (" << info.motion << "), wind " << -info.free_stream[0] << " m/s, trim at "
              << run.trim().controls.collective << " % collective, pitch " << run.trim().pitch * 180 / M_PI << " deg; inflow "
              << cfg.inflow;
    if (auto* d = run.lrm_domain())
      std::cout << " (N = " << d->config().nodes << ", a = " << d->config().reach << ", " << d->cells_per_edge() << "^3 cells, "
                << d->solver().backend_name() << ", LBM step " << d->time_step() * 1e3 << " ms, faces " << o->faces.label() << ")";
    std::cout << "\n";
    if (o->no_rotor_forces)
      std::cout << "approach: --no-rotor-forces: the rotor's forces stay off the LRM's fluid, so its loads are those of a rotor "
                   "without its own induced flow (a diagnostic of the domain's air, not a flight)\n";
    std::ofstream csv(dir / "approach.csv");
    write_header(csv);
    write_row(csv, run.sample());
    double next_row = o->output_interval, next_report = 2.0;
    lrm::WallClockPacer pacer(run.time());
    lrm::SliceAverage plane;
    double next_plane = o->plane_from.value_or(0.0);
    lrm::DeadlineWatch deadline_watch;
    while (!run.done()) {
      if (o->realtime) run.set_deadline(pacer.due(run.time() + run.time_step()));
      run.step();
      if (o->realtime) pacer.wait_until(run.time());
      if (const auto* rt = run.realtime_inflow()) {
        const std::string late = deadline_watch.update(run.time(), rt->stats());
        if (!late.empty()) std::cerr << "approach: warning: " << late << "\n";
      }
      const lrm::ApproachSample& s = run.sample();
      if (!std::isfinite(s.thrust))
        throw std::runtime_error("approach: the rotor loads are not finite at t = " + std::to_string(s.time) + " s");
      if (o->plane_from && s.time >= next_plane - 0.5 * run.time_step()) {
        lrm::DomainSlice slice = lrm::domain_slice(*run.lrm_domain(), 1);
        lrm::add_undisturbed_air(*run.lrm_domain(), slice);
        plane.add(slice);
        next_plane += kPlaneSampleInterval;
      }
      if (s.time >= next_row - 0.5 * run.time_step()) {
        write_row(csv, s);
        next_row += o->output_interval;
      }
      if (s.time >= next_report - 0.5 * run.time_step()) {
        std::cout << std::fixed << std::setprecision(1) << "  t = " << s.time << " s, " << s.distance << " m behind the spot, "
                  << s.height_above_deck << " m above the deck, C_T " << std::setprecision(5) << s.ct << ", LRM wall cells " << s.wall_cells
                  << ", t_clock/t_sim " << std::setprecision(2) << run.wall_seconds() / s.time;
        if (const auto* rt = run.realtime_inflow())
          std::cout << ", deadline misses " << rt->stats().deadline_misses << " of " << rt->stats().steps;
        std::cout << "\n" << std::defaultfloat << std::flush;
        next_report += 2.0;
      }
    }
    csv.close();
    if (!run.end_reason().empty()) std::cout << "approach: free flight " << run.end_reason() << "\n";
    std::cout << "wrote " << (dir / "approach.csv").string() << " (" << run.sample().time << " s simulated, " << run.wall_seconds()
              << " s in the coupled step: t_clock/t_sim " << run.wall_seconds() / run.sample().time << ")\n";
    if (const auto n = run.fluid_counts(); n && n->wall_changes > 0)
      std::cout << "LRM walls: the wall cells changed " << n->wall_changes << " times (" << n->face_restarts
                << " of them next to the faces, where the flow restarts at equilibrium); placing walls took " << n->wall_seconds << " s\n";
    if (plane.samples() > 0) {
      write_plane(dir, "centre_plane_mean", plane.mean(), run.helicopter().parameters().main_rotor.radius, !o->no_plot);
      std::cout << "wrote " << (dir / "centre_plane_mean.csv").string() << " (" << plane.samples() << " samples from " << *o->plane_from
                << " s)\n";
    }
    if (const auto* d = run.lrm_domain(); d && d->config().rotor_far_field)
      std::cout << "rotor far field at the faces: its shape was computed " << d->far_field_builds() << " times (" << d->far_field_seconds()
                << " s), rescaled with the thrust in between\n";
    if (const auto* rt = run.realtime_inflow()) {
      const lrm::RealTimeStats st = rt->stats();
      std::cout << "real time ("
                << (o->pipelined ? "pipelined, the LRM " + std::to_string(lrm::kPipelineDepth) + " LBM intervals behind" : "lock-step")
                << "): " << st.deadline_misses << " of " << st.steps << " steps missed their inflow deadline ("
                << 100.0 * st.miss_fraction() << " %) and flew on Pitt-Peters; " << pacer.overruns()
                << " steps ended after their due time; the LRM dropped " << run.dropped_lrm_steps() << " LBM steps to catch up\n";
    }
    if (!o->no_plot && run.sample().time <= cfg.startup) {
      std::cout << "approach: no plots: the run ended before the start-up period (" << cfg.startup
                << " s) was over, so there is no Delta to take\n";
    } else if (!o->no_plot) {
      if (!run_script("analyze_approach.py",
                      "'" + (dir / "approach.csv").string() + "' --out '" + dir.string() + "' --startup " + std::to_string(cfg.startup)))
        std::cerr << "ship_lrm: warning: the analysis failed (needs python3 with numpy, matplotlib and pywt); the CSV is complete\n";
    }
    return 0;
  };
}

}  // namespace ship_lrm::tools
