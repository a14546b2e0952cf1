// `ship_lrm sweep inflow`: isolated rotor in the LRM domain over a range of speeds against
// Pitt-Peters and momentum theory (thesis 8.1, figs. 8.1 and 8.2), CSV + PNG.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>

#include "commands.hpp"
#include "ship_lrm/lrm/inflow_sweep.hpp"
#include "ship_lrm/rotor/momentum_theory.hpp"

namespace ship_lrm::tools {
namespace fs = std::filesystem;

std::function<int()> add_sweep_command(CLI::App& app) {
  auto* sweep = app.add_subcommand("sweep", "Parameter sweeps of the LRM domain");
  sweep->require_subcommand(1);
  auto* inflow =
      sweep->add_subcommand("inflow", "Isolated rotor, uniform thrust, zero incidence: LRM inflow against Pitt-Peters (thesis 8.1)");
  struct Opts {
    int nodes = 64;
    double reach = 1.25, thrust = 24525, settle = 4, average = 2;
    std::string speeds = "0:5:65", backend = "auto", out;
    bool overwrite = false, no_plot = false;
  };
  auto o = std::make_shared<Opts>();
  inflow->add_option("--N", o->nodes, "lattice nodes per 4R")->check(CLI::Range(16, 512))->capture_default_str();
  inflow->add_option("--reach", o->reach, "domain edge / 4R (a >= 1)")->check(CLI::Range(1.0, 8.0))->capture_default_str();
  inflow->add_option("--speeds", o->speeds, "speeds in m/s: start:step:stop or a comma list")->capture_default_str();
  inflow->add_option("--thrust", o->thrust, "N, uniform over the disk")->check(CLI::Range(1.0, 1e6))->capture_default_str();
  inflow->add_option("--settle", o->settle, "s simulated before averaging")->check(CLI::Range(0.0, 600.0))->capture_default_str();
  inflow->add_option("--average", o->average, "s averaged")->check(CLI::Range(0.01, 600.0))->capture_default_str();
  inflow->add_option("--backend", o->backend, "cpu, cuda or auto")->check(CLI::IsMember({"cpu", "cuda", "auto"}))->capture_default_str();
  inflow->add_option("--out", o->out, "output directory (inflow_sweep.csv, .png)")->required();
  inflow->add_flag("--overwrite", o->overwrite, "replace existing output files");
  inflow->add_flag("--no-plot", o->no_plot, "write the CSV only");
  return [o, inflow]() -> int {
    if (!inflow->parsed()) return -1;
    const auto speeds = parse_speeds(o->speeds);
    lrm::LrmConfig cfg;
    cfg.nodes = o->nodes;
    cfg.reach = o->reach;
    cfg.backend = lbm::parse_backend(o->backend);
    const fs::path dir(o->out);
    prepare_output(dir, {"inflow_sweep.csv", "inflow_sweep.png"}, o->overwrite);
    const auto case_config = [&](double v) { return lrm::config_for_stream(cfg, v); };
    for (double v : speeds) {  // check every set-up before any long run
      lrm::LrmDomain probe(case_config(v));
      probe.set_stream(rotor::Vec3(-v, 0, 0));
    }
    std::ofstream csv(dir / "inflow_sweep.csv");
    csv << "speed_m_s,lrm_mean_m_s,lrm_cosine_m_s,lrm_sine_m_s,lrm_inplane_x_m_s,pitt_peters_mean_m_s,pitt_peters_cosine_m_s,"
           "momentum_theory_m_s,hover_momentum_theory_m_s,mean_over_pitt_peters,N,reach,cells_per_edge,time_step_s,steps,wall_s\n";
    const double vh = rotor::hover_induced_velocity(o->thrust, cfg.density, cfg.radius);
    for (double v : speeds) {
      lrm::IsolatedRotorCase c;
      c.speed = v;
      c.thrust = o->thrust;
      c.settle = o->settle;
      c.average = o->average;
      const auto r = lrm::run_isolated_rotor(case_config(v), c);
      std::cout << std::fixed << std::setprecision(3) << "V = " << v << " m/s: LRM mean " << r.induced_mean << " m/s, Pitt-Peters "
                << r.pitt_peters_mean << " (ratio " << r.induced_mean / r.pitt_peters_mean << "); cosine " << r.inflow.cosine.z() << " vs "
                << r.pitt_peters_cosine << "; " << r.steps << " steps in " << std::setprecision(1) << r.wall_seconds << " s\n";
      csv << std::setprecision(6) << v << "," << r.induced_mean << "," << r.inflow.cosine.z() << "," << r.inflow.sine.z() << ","
          << r.inflow.mean.x() << "," << r.pitt_peters_mean << "," << r.pitt_peters_cosine << "," << r.momentum_theory << "," << vh << ","
          << r.induced_mean / r.pitt_peters_mean << "," << cfg.nodes << "," << cfg.reach << "," << r.cells_per_edge << ","
          << r.simulated_seconds / r.steps << "," << r.steps << "," << r.wall_seconds << "\n";
      csv.flush();
    }
    csv.close();
    std::cout << "wrote " << (dir / "inflow_sweep.csv").string() << "\n";
    if (!o->no_plot) plot("sweep_inflow", dir / "inflow_sweep.csv", dir / "inflow_sweep.png", "");
    return 0;
  };
}

}  // namespace ship_lrm::tools
