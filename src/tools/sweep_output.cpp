// Shared helpers of the sweep commands: speed lists (number_list.cpp), output directories, plotting.
#include <cstdlib>
#include <iostream>

#include "commands.hpp"
#include "ship_lrm/flight/parameters.hpp"

namespace ship_lrm::tools {
namespace fs = std::filesystem;

std::vector<double> parse_speeds(const std::string& text) { return parse_number_list(text, "--speeds", 0.0, 100.0, "m/s"); }

// Refuses to overwrite a user's files unless asked to.
void prepare_output(const fs::path& dir, const std::vector<std::string>& names, bool overwrite) {
  fs::create_directories(dir);
  for (const auto& n : names)
    if (fs::exists(dir / n) && !overwrite) throw std::runtime_error((dir / n).string() + " exists; pass --overwrite to replace it");
}

bool run_script(const std::string& script, const std::string& args) {
  const std::string python = fs::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
  const std::string cmd = python + " '" + flight::shipped_directory("SHIP_LRM_SCRIPTS_DIR", "scripts") + "/" + script + "' " + args;
  return std::system(cmd.c_str()) == 0;
}

// Plot with Debian's python3 + matplotlib; a missing plotter is a warning, the CSV stays.
void plot(const std::string& kind, const fs::path& csv, const fs::path& png, const std::string& reference) {
  std::string args = kind + " '" + csv.string() + "' '" + png.string() + "'";
  if (!reference.empty()) args += " --reference '" + reference + "'";
  if (!run_script("plot_flight.py", args))
    std::cerr << "ship_lrm: warning: plotting failed (needs python3 with matplotlib); the CSV " << csv << " is complete\n";
  else
    std::cout << "wrote " << png.string() << "\n";
}

}  // namespace ship_lrm::tools
