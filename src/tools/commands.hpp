// Sub-commands of the `ship_lrm` command-line program; each file registers one.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>

namespace ship_lrm::tools {

// Each returns the action of its sub-command: it returns -1 when that sub-command was not chosen,
// else the exit code.
std::function<int()> add_bench_command(CLI::App& app);
std::function<int()> add_units_command(CLI::App& app);
std::function<int()> add_validate_command(CLI::App& app);
#ifdef SHIP_LRM_HAVE_FLIGHT
std::function<int()> add_trim_command(CLI::App& app);
std::function<int()> add_doublet_command(CLI::App& app);
#endif

}  // namespace ship_lrm::tools
