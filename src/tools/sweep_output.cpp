// Shared helpers of the sweep commands: speed lists, output directories, plotting.
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <sstream>

#include "commands.hpp"
#include "ship_lrm/flight/parameters.hpp"

namespace ship_lrm::tools {
namespace fs = std::filesystem;

std::vector<double> parse_speeds(const std::string& text) {
  std::vector<double> v;
  const auto num = [&](const std::string& s) {
    size_t pos = 0;
    double x = 0;
    try {
      x = std::stod(s, &pos);
    } catch (const std::exception&) {
      pos = 0;
    }
    if (pos != s.size() || !std::isfinite(x)) throw CLI::ValidationError("--speeds", "'" + s + "' is not a number");
    return x;
  };
  if (text.find(':') != std::string::npos) {
    std::stringstream ss(text);
    std::string a, b, c;
    if (!std::getline(ss, a, ':') || !std::getline(ss, b, ':') || !std::getline(ss, c) || c.find(':') != std::string::npos)
      throw CLI::ValidationError("--speeds", "expected start:step:stop, e.g. 0:5:70");
    const double start = num(a), step = num(b), stop = num(c);
    if (step <= 0 || stop < start) throw CLI::ValidationError("--speeds", "needs step > 0 and stop >= start");
    for (int i = 0; start + i * step <= stop + 1e-9; ++i) v.push_back(start + i * step);
  } else {
    std::stringstream ss(text);
    std::string a;
    while (std::getline(ss, a, ',')) v.push_back(num(a));
  }
  if (v.empty() || v.size() > 400) throw CLI::ValidationError("--speeds", "needs 1 to 400 speeds");
  for (double x : v)
    if (x < 0 || x > 100) throw CLI::ValidationError("--speeds", "speeds must lie in 0..100 m/s");
  return v;
}

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
