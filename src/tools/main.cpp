// ship_lrm: command-line entry point (sub-commands in cmd_*.cpp).
#include <exception>
#include <iostream>
#include <vector>

#include "commands.hpp"
#include "ship_lrm/lbm/lattice.hpp"
#include "ship_lrm/lbm/solver.hpp"
#ifdef SHIP_LRM_HAVE_FLIGHT
#include "ship_lrm/flight/parameters.hpp"
#include "ship_lrm/wake/wake_table.hpp"
#endif

int main(int argc, char** argv) {
  CLI::App app{"ship_lrm - Local Recalculation Model: lattice-Boltzmann rotor / ship air-wake simulation"};
  app.require_subcommand(1);
  std::vector<std::function<int()>> actions = {ship_lrm::tools::add_bench_command(app), ship_lrm::tools::add_units_command(app),
                                               ship_lrm::tools::add_validate_command(app)};
#ifdef SHIP_LRM_HAVE_FLIGHT
  actions.push_back(ship_lrm::tools::add_trim_command(app));
  actions.push_back(ship_lrm::tools::add_doublet_command(app));
  actions.push_back(ship_lrm::tools::add_sweep_command(app));
  actions.push_back(ship_lrm::tools::add_wake_command(app));
  actions.push_back(ship_lrm::tools::add_approach_command(app));
#endif
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help prints and succeeds; every malformed command line is invalid input (exit code 2)
    const int rc = app.exit(e);
    return rc == 0 ? 0 : 2;
  }
  try {
    ship_lrm::tools::reject_non_finite_numbers(app);
    for (auto& action : actions) {
      const int rc = action();  // -1: its sub-command was not chosen
      if (rc >= 0) return rc;
    }
  } catch (const CLI::ValidationError& e) {
    std::cerr << "ship_lrm: invalid input: " << e.what() << "\n";
    return 2;
  } catch (const ship_lrm::ConfigError& e) {
    std::cerr << "ship_lrm: invalid input: " << e.what() << "\n";
    return 2;
  } catch (const ship_lrm::lbm::DivergenceError& e) {
    std::cerr << "ship_lrm: " << e.what() << "\n";
    return 3;
#ifdef SHIP_LRM_HAVE_FLIGHT
  } catch (const ship_lrm::flight::ParameterError& e) {
    std::cerr << "ship_lrm: invalid input: " << e.what() << "\n";
    return 2;
  } catch (const ship_lrm::wake::TableError& e) {
    std::cerr << "ship_lrm: invalid input: " << e.what() << "\n";
    return 2;
#endif
  } catch (const std::invalid_argument& e) {  // e.g. controls outside their travel, bad doublet settings
    std::cerr << "ship_lrm: invalid input: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "ship_lrm: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
