// Probe points of a ship-wake run (see probe_points.hpp).
#include "ship_lrm/wake/probe_points.hpp"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "ship_lrm/lbm/lattice.hpp"

namespace ship_lrm::wake {

ProbeFrame parse_probe_frame(const std::string& name) {
  if (name == "ship") return ProbeFrame::Ship;
  if (name == "tunnel") return ProbeFrame::Tunnel;
  throw ConfigError("unknown probe frame '" + name + "' (ship or tunnel)");
}

std::string to_string(ProbeFrame f) { return f == ProbeFrame::Ship ? "ship" : "tunnel"; }

std::array<double, 3> to_ship_frame(const std::array<double, 3>& p, ProbeFrame frame, double factor) {
  const double s = 1.0 / factor;
  if (frame == ProbeFrame::Ship) return {p[0] * s, p[1] * s, p[2] * s};
  return {-p[0] * s, p[1] * s, -p[2] * s};
}

std::array<double, 3> from_ship_frame(const std::array<double, 3>& p, ProbeFrame frame, double factor) {
  if (frame == ProbeFrame::Ship) return {p[0] * factor, p[1] * factor, p[2] * factor};
  return {-p[0] * factor, p[1] * factor, -p[2] * factor};
}

std::vector<std::array<double, 3>> read_probe_csv(const std::string& path) {
  if (std::filesystem::is_directory(path)) throw ConfigError("probes: '" + path + "' is a directory, not a CSV file");
  if (!std::filesystem::is_regular_file(path)) throw ConfigError("probes: '" + path + "' does not exist or is not a regular file");
  std::ifstream in(path);
  if (!in) throw ConfigError("probes: cannot read '" + path + "'");
  std::vector<std::array<double, 3>> points;
  std::string line;
  bool first_row = true;
  for (int number = 1; std::getline(in, line); ++number) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const auto first = line.find_first_not_of(" \t");
    if (first == std::string::npos || line[first] == '#') continue;
    std::array<double, 3> p{};
    std::stringstream row(line);
    std::string cell;
    int n = 0;
    bool numbers = true;
    while (std::getline(row, cell, ',')) {
      char* end = nullptr;
      const double v = std::strtod(cell.c_str(), &end);
      const bool is_number =
          end != cell.c_str() && cell.find_first_not_of(" \t", static_cast<std::size_t>(end - cell.c_str())) == std::string::npos;
      if (!is_number) numbers = false;
      if (n < 3) p[n] = v;
      ++n;
    }
    const bool header = !numbers && first_row;  // a first row of names
    first_row = false;
    if (header) continue;
    if (!numbers || n != 3)
      throw ConfigError("probes: '" + path + "' line " + std::to_string(number) + ": expected three numbers x,y,z (m), got '" + line + "'");
    for (double v : p)
      if (!std::isfinite(v)) throw ConfigError("probes: '" + path + "' line " + std::to_string(number) + ": a value is not finite");
    points.push_back(p);
    if (points.size() > 10000) throw ConfigError("probes: '" + path + "' has more than 10000 points");
  }
  if (points.empty()) throw ConfigError("probes: '" + path + "' holds no points");
  return points;
}

}  // namespace ship_lrm::wake
