// `ship_lrm sweep inflow` and `sweep ground`: isolated rotor in the LRM domain over speeds (against
// Pitt-Peters and momentum theory, thesis 8.1) or ground heights (thesis 8.2.3), CSV + PNG.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "commands.hpp"
#include "lrm_face_options.hpp"
#include "ship_lrm/lbm/lattice.hpp"
#include "ship_lrm/lrm/inflow_sweep.hpp"
#include "ship_lrm/rotor/momentum_theory.hpp"

namespace ship_lrm::tools {
namespace fs = std::filesystem;

namespace {

constexpr double kLowestHeight = 0.25;  // z/R, sweep ground

// Options both isolated-rotor sweeps share: the domain, the rotor's load and averaging, the output.
struct IsolatedRotorOptions {
  int nodes = 64;
  double reach = 1.25, thrust = 24525, settle = 4, average = 2, lattice_velocity = lrm::LrmConfig{}.reference_velocity;
  LrmFaceOptions face;
  std::string backend = "auto", out;
  bool overwrite = false, no_plot = false, planes = false;

  void add_to(CLI::App& cmd, const std::string& outputs) {
    cmd.add_option("--N", nodes, "lattice nodes per 4R")->check(CLI::Range(16, 512))->capture_default_str();
    cmd.add_option("--reach", reach, "domain edge / 4R (a >= 1)")->check(CLI::Range(1.0, 8.0))->capture_default_str();
    cmd.add_option("--thrust", thrust, "N, uniform over the disk")->check(CLI::Range(1.0, 1e6))->capture_default_str();
    cmd.add_option("--settle", settle, "s simulated before averaging")->check(CLI::Range(0.0, 600.0))->capture_default_str();
    cmd.add_option("--average", average, "s averaged")->check(CLI::Range(0.01, 600.0))->capture_default_str();
    cmd.add_option("--backend", backend, "cpu, cuda or auto")->check(CLI::IsMember({"cpu", "cuda", "auto"}))->capture_default_str();
    cmd.add_option("--lattice-velocity", lattice_velocity,
                   "m/s the lattice maps to Mach 0.3 (thesis table 6.4: 30), raised to a case's stream when that is faster; "
                   "a larger value lowers the lattice Mach number (compressibility check) and shrinks the time step")
        ->check(CLI::Range(1.0, 1e4))
        ->capture_default_str();
    face.add_to(cmd);
    cmd.add_option("--out", out, "output directory (" + outputs + ")")->required();
    cmd.add_flag("--overwrite", overwrite, "replace existing output files");
    cmd.add_flag("--no-plot", no_plot, "write the CSV only");
    cmd.add_flag("--planes", planes,
                 "also write each case's time-averaged x-z plane through the hub (plane_*.csv, .png: velocity relative to the "
                 "rotor, streamlines)");
  }
  lrm::LrmConfig config() const {
    lrm::LrmConfig cfg;
    cfg.nodes = nodes;
    cfg.reach = reach;
    cfg.reference_velocity = lattice_velocity;
    cfg.backend = lbm::parse_backend(backend);
    face.apply(cfg);
    return cfg;
  }
  lrm::IsolatedRotorCase rotor_case(double speed) const {
    lrm::IsolatedRotorCase c;
    c.speed = speed;
    c.thrust = thrust;
    c.settle = settle;
    c.average = average;
    c.centre_plane = planes;
    return c;
  }
};

// One case with a progress line on stderr (it takes minutes to hours at N = 64 - 128).
lrm::IsolatedRotorResult run_with_progress(const lrm::LrmConfig& cfg, lrm::IsolatedRotorCase c, const std::string& label) {
  ProgressLine bar(label);
  c.progress = [&bar](double fraction) { bar.update(fraction); };
  return lrm::run_isolated_rotor(cfg, c);
}

// The averaged centre plane of one case: CSV (x, z in m from the hub, FRD; velocity relative to the
// rotor in m/s; wall 0/1) and, unless --no-plot, a PNG.
std::function<int()> add_ground_sweep(CLI::App& sweep) {
  auto* ground = sweep.add_subcommand(
      "ground",
      "Isolated rotor above a ground plane: v_mean / v_mean(out of ground effect) against Cheeseman-Bennett and Hayden (thesis 8.2.3)");
  struct Opts : IsolatedRotorOptions {
    std::string mode = "hover", heights, speeds = "0,3,6,9,12,15";
    std::string ground_wall = "no-slip";
    bool fuselage = false;
  };
  auto o = std::make_shared<Opts>();
  ground->add_flag("--fuselage", o->fuselage, "add the Bo 105-like fuselage (walls.hpp) below the disk");
  ground
      ->add_option("--ground", o->ground_wall,
                   "the ground's wall: no-slip (moving-wall bounce-back) or slip (specular reflection, the inviscid ground of the "
                   "image models, for the wall jet the cells cannot resolve); a slip ground is named in the CSV's faces column")
      ->check(CLI::IsMember({"slip", "no-slip"}))
      ->capture_default_str();
  ground
      ->add_option("--mode", o->mode,
                   "hover (heights swept; there --faces defaults to ambient) or forward (speeds swept at each height; there "
                   "--lattice-velocity defaults to " +
                       tag(lrm::kForwardGroundLatticeVelocity) + ")")
      ->check(CLI::IsMember({"hover", "forward"}))
      ->capture_default_str();
  ground->add_option("--heights", o->heights,
                     "hub height over ground z/R, at least 0.25: a comma list or start:step:stop (default hover "
                     "0.5,0.6,0.7,0.8,1,1.25,1.5,2; forward 0.5,0.6,0.8,1)");
  ground->add_option("--speeds", o->speeds, "forward mode: speeds in m/s")->capture_default_str();
  o->add_to(*ground, "ground_sweep.csv, .png");
  return [o, ground]() -> int {
    if (!ground->parsed()) return -1;
    const bool hover = o->mode == "hover";
    if (hover && ground->get_option("--speeds")->count() > 0)
      throw ConfigError("--speeds applies to --mode forward (hover sweeps the heights at zero speed)");
    const auto heights = parse_number_list(o->heights.empty() ? (hover ? "0.5,0.6,0.7,0.8,1,1.25,1.5,2" : "0.5,0.6,0.8,1") : o->heights,
                                           "--heights", 0.0, 1000.0, "R");
    const auto speeds = hover ? std::vector<double>{0.0} : parse_speeds(o->speeds);
    // Below z/R = 1/4 Cheeseman-Bennett's 1 - (R / 4z)^2 is negative, and the disk all but sits on the
    // ground (a Bo 105 on its skids has its hub at 0.55 R: 1.49 m above the cg, the skids 1.2 m below
    // it): refused rather than swept into nonsense.
    for (double h : heights)
      if (!(h >= kLowestHeight)) {
        std::ostringstream what;
        what << "--heights: z/R must be at least " << kLowestHeight
             << " (below it Cheeseman-Bennett's 1 - (R/4z)^2 is negative and the disk all but sits on the ground), got " << h;
        throw ConfigError(what.str());
      }
    if (hover && ground->get_option("--faces")->count() == 0) {
      o->face.faces = "ambient";
      std::cout << "hover in ground effect: faces ambient (entraining pressure faces; the thesis' faces hold the wall jet in: "
                   "--faces thesis)\n";
    }
    const bool slip_ground = o->ground_wall == "slip";
    if (!hover && ground->get_option("--lattice-velocity")->count() == 0) {
      o->lattice_velocity = lrm::kForwardGroundLatticeVelocity;
      std::cout << "forward flight in ground effect: lattice velocity " << o->lattice_velocity
                << " m/s (half the thesis' lattice Mach number; --lattice-velocity sets it)\n";
    }
    const lrm::LrmConfig cfg = o->config();
    const fs::path dir(o->out);
    const auto plane_stem = [](double v, double z_over_R) {
      return "plane_V" + tag(v) + (z_over_R > 0 ? "_z" + tag(z_over_R) : std::string("_oge"));
    };
    std::vector<std::string> outputs{"ground_sweep.csv", "ground_sweep.png"};
    if (o->planes)
      for (double v : speeds) {
        add_plane_outputs(outputs, plane_stem(v, 0));
        for (double h : heights) add_plane_outputs(outputs, plane_stem(v, h));
      }
    const auto case_for = [&](double v, double z_over_R) {
      lrm::IsolatedRotorCase c = o->rotor_case(v);
      c.ground_height = z_over_R * cfg.radius;  // 0: out of ground effect
      c.fuselage = o->fuselage;
      c.slip_ground = slip_ground && z_over_R > 0;
      return c;
    };
    // Every case's set-up is checked before any long run and before any file is made (a ground on the
    // disk's cells was found only after the run out of ground effect, and left a CSV that blocked the rerun).
    for (double v : speeds) {
      const lrm::LrmConfig run_cfg = lrm::config_for_stream(cfg, v);
      lrm::check_isolated_rotor(run_cfg, case_for(v, 0));
      for (double h : heights) {
        try {
          lrm::check_isolated_rotor(run_cfg, case_for(v, h));
        } catch (const ConfigError& e) {
          std::ostringstream what;
          what << "--heights: z/R = " << h << " at N = " << cfg.nodes << ", a = " << cfg.reach << ": " << e.what();
          throw ConfigError(what.str());
        }
      }
    }
    prepare_output(dir, outputs, o->overwrite);
    std::ofstream csv(dir / "ground_sweep.csv");
    csv << "mode,speed_m_s,z_over_R,z_effective_over_R,lrm_mean_m_s,lrm_mean_oge_m_s,ratio,cheeseman_bennett,hayden,"
           "momentum_theory_oge_m_s,faces,N,reach,steps,wall_s,lrm_std_m_s,lrm_half_difference_m_s,oge_std_m_s,oge_half_difference_m_s,"
           "ratio_uncertainty\n";
    for (double v : speeds) {
      const auto run_cfg = lrm::config_for_stream(cfg, v);
      const auto oge = run_with_progress(run_cfg, case_for(v, 0), case_label(v, 0));
      if (o->planes) write_plane(dir, plane_stem(v, 0), oge.centre_plane, cfg.radius, !o->no_plot);
      const double vi = rotor::glauert_induced_velocity(o->thrust, cfg.density, cfg.radius, v);
      std::cout << std::fixed << std::setprecision(3) << "V = " << v << " m/s, out of ground effect: v_mean " << oge.induced_mean
                << " m/s +- " << std::abs(oge.induced_half_difference) << " (momentum theory " << vi << ")" << std::endl;
      for (double h : heights) {
        const auto r = run_with_progress(run_cfg, case_for(v, h), case_label(v, h));
        if (o->planes) write_plane(dir, plane_stem(v, h), r.centre_plane, cfg.radius, !o->no_plot);
        const double ratio = r.induced_mean / oge.induced_mean;
        // the half-window differences of both means, combined (see IsolatedRotorResult)
        const double uncertainty =
            std::abs(ratio) * std::hypot(r.induced_half_difference / r.induced_mean, oge.induced_half_difference / oge.induced_mean);
        const double cb = lrm::cheeseman_bennett_ratio(h, v, vi);
        std::cout << "  z/R = " << h << ": v_mean " << r.induced_mean << " m/s, ratio " << ratio << " +- " << uncertainty
                  << " (Cheeseman-Bennett " << cb;
        if (hover) std::cout << ", Hayden " << lrm::hayden_ratio(h);
        std::cout << "); " << r.steps << " steps in " << std::setprecision(1) << r.wall_seconds << " s\n" << std::setprecision(3);
        csv << std::setprecision(6) << o->mode << "," << v << "," << h << "," << r.ground_effective_height / cfg.radius << ","
            << r.induced_mean << "," << oge.induced_mean << "," << ratio << "," << cb << ",";
        if (hover) csv << lrm::hayden_ratio(h);
        csv << "," << vi << "," << o->face.label() << (slip_ground ? ";slip-ground" : "") << "," << cfg.nodes << "," << cfg.reach << ","
            << r.steps << "," << r.wall_seconds << "," << r.induced_std << "," << r.induced_half_difference << "," << oge.induced_std << ","
            << oge.induced_half_difference << "," << uncertainty << "\n";
        csv.flush();
        std::cout.flush();
      }
    }
    csv.close();
    std::cout << "wrote " << (dir / "ground_sweep.csv").string() << "\n";
    if (!o->no_plot) plot("sweep_ground", dir / "ground_sweep.csv", dir / "ground_sweep.png", "");
    return 0;
  };
}

}  // namespace

std::function<int()> add_sweep_command(CLI::App& app) {
  auto* sweep = app.add_subcommand("sweep", "Parameter sweeps of the LRM domain");
  sweep->require_subcommand(1);
  auto* inflow =
      sweep->add_subcommand("inflow", "Isolated rotor, uniform thrust, zero incidence: LRM inflow against Pitt-Peters (thesis 8.1)");
  struct Opts : IsolatedRotorOptions {
    std::string speeds = "0:5:65";
    double climb = 0;
  };
  auto o = std::make_shared<Opts>();
  inflow->add_option("--speeds", o->speeds, "speeds in m/s: start:step:stop or a comma list")->capture_default_str();
  inflow
      ->add_option("--climb", o->climb,
                   "axial climb rate in m/s for every case (air through the disk from above; in a pure climb momentum theory is "
                   "exact for the uniformly loaded disk)")
      ->check(CLI::Range(0.0, 200.0))
      ->capture_default_str();
  o->add_to(*inflow, "inflow_sweep.csv, .png");
  auto run_ground = add_ground_sweep(*sweep);
  auto run_free_wake = add_free_wake_sweep(*sweep);
  return [o, inflow, run_ground, run_free_wake]() -> int {
    if (const int r = run_free_wake(); r >= 0) return r;
    if (!inflow->parsed()) return run_ground();
    const auto speeds = parse_speeds(o->speeds);
    const lrm::LrmConfig cfg = o->config();
    const fs::path dir(o->out);
    std::vector<std::string> outputs{"inflow_sweep.csv", "inflow_sweep.png"};
    if (o->planes)
      for (double v : speeds) add_plane_outputs(outputs, "plane_V" + tag(v));
    const auto case_config = [&](double v) { return lrm::config_for_stream(cfg, std::hypot(v, o->climb)); };
    const auto rotor_case = [&](double v) {
      lrm::IsolatedRotorCase c = o->rotor_case(v);
      c.climb = o->climb;
      return c;
    };
    for (double v : speeds) lrm::check_isolated_rotor(case_config(v), rotor_case(v));  // before any long run or file
    prepare_output(dir, outputs, o->overwrite);
    std::ofstream csv(dir / "inflow_sweep.csv");
    csv << "speed_m_s,lrm_mean_m_s,lrm_cosine_m_s,lrm_sine_m_s,lrm_inplane_x_m_s,pitt_peters_mean_m_s,pitt_peters_cosine_m_s,"
           "momentum_theory_m_s,hover_momentum_theory_m_s,mean_over_pitt_peters,N,reach,cells_per_edge,time_step_s,steps,wall_s,"
           "lrm_mean_std_m_s,lrm_mean_half_difference_m_s,faces,climb_m_s\n";
    const double vh = rotor::hover_induced_velocity(o->thrust, cfg.density, cfg.radius);
    for (double v : speeds) {
      const auto r = run_with_progress(case_config(v), rotor_case(v), case_label(v, 0, o->climb));
      if (o->planes) write_plane(dir, "plane_V" + tag(v), r.centre_plane, cfg.radius, !o->no_plot);
      std::cout << std::fixed << std::setprecision(3) << case_label(v, 0, o->climb) << ": LRM mean " << r.induced_mean
                << " m/s, Pitt-Peters " << r.pitt_peters_mean << " (ratio " << r.induced_mean / r.pitt_peters_mean << "); cosine "
                << r.inflow.cosine.z() << " vs " << r.pitt_peters_cosine << "; " << r.steps << " steps in " << std::setprecision(1)
                << r.wall_seconds << " s\n";
      csv << std::setprecision(6) << v << "," << r.induced_mean << "," << r.inflow.cosine.z() << "," << r.inflow.sine.z() << ","
          << r.inflow.mean.x() << "," << r.pitt_peters_mean << "," << r.pitt_peters_cosine << "," << r.momentum_theory << "," << vh << ","
          << r.induced_mean / r.pitt_peters_mean << "," << cfg.nodes << "," << cfg.reach << "," << r.cells_per_edge << ","
          << r.simulated_seconds / r.steps << "," << r.steps << "," << r.wall_seconds << "," << r.induced_std << ","
          << r.induced_half_difference << "," << o->face.label() << "," << o->climb << "\n";
      csv.flush();
    }
    csv.close();
    std::cout << "wrote " << (dir / "inflow_sweep.csv").string() << "\n";
    if (!o->no_plot) plot("sweep_inflow", dir / "inflow_sweep.csv", dir / "inflow_sweep.png", "");
    return 0;
  };
}

}  // namespace ship_lrm::tools
