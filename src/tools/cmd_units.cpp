// `ship_lrm units`: physical <-> lattice conversion of a domain (thesis tables 6.2-6.4).
#include <iomanip>
#include <iostream>

#include "commands.hpp"
#include "ship_lrm/lbm/units.hpp"

namespace ship_lrm::tools {

std::function<int()> add_units_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("units", "Lattice spacing, time step and relaxation time of a domain (defaults: the LRM at N = 64)");
  auto ref = std::make_shared<lbm::UnitReference>();
  ref->length = 4 * 4.92;  // LRM: 4R, R = 4.92 m (thesis table 6.4)
  ref->nodes = 64;
  ref->velocity = 30.0;
  ref->viscosity = 1.46072e-4;
  ref->density = 1.1934;
  cmd->add_option("--length", ref->length, "reference length l_ref [m]")->capture_default_str();
  cmd->add_option("--nodes", ref->nodes, "lattice nodes N across l_ref")->capture_default_str();
  cmd->add_option("--velocity", ref->velocity, "reference velocity [m/s]")->capture_default_str();
  cmd->add_option("--viscosity", ref->viscosity, "kinematic viscosity [m^2/s]")->capture_default_str();
  cmd->add_option("--density", ref->density, "density [kg/m^3]")->capture_default_str();
  cmd->add_option("--lattice-velocity", ref->lattice_velocity, "reference velocity in lattice units")->capture_default_str();
  return [ref, cmd]() -> int {
    if (!cmd->parsed()) return -1;
    const lbm::UnitConverter u(*ref);
    std::cout << std::setprecision(6) << "dx = " << u.dx() << " m\ndt = " << u.dt() * 1e3 << " ms\nnu_lattice = " << u.lattice_viscosity()
              << "\ntau = " << u.relaxation_time() << "\nMach (reference) = " << u.mach_number() << "\n";
    return 0;
  };
}

}  // namespace ship_lrm::tools
