// Shared helpers of the sweep commands: speed lists (number_list.cpp), output directories, plotting.
#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "commands.hpp"
#include "ship_lrm/flight/parameters.hpp"

namespace ship_lrm::tools {
namespace fs = std::filesystem;

std::vector<double> parse_speeds(const std::string& text) { return parse_number_list(text, "--speeds", 0.0, 100.0, "m/s"); }

bool run_script(const std::string& script, const std::string& args) {
  const std::string python = fs::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
  const std::string cmd = python + " '" + flight::shipped_directory("SHIP_LRM_SCRIPTS_DIR", "scripts") + "/" + script + "' " + args;
  return std::system(cmd.c_str()) == 0;
}

namespace {
// The comma-separated fields of one line (a trailing carriage return dropped).
std::vector<std::string> csv_fields(std::string line) {
  if (!line.empty() && line.back() == '\r') line.pop_back();
  std::vector<std::string> fields;
  std::stringstream ss(line);
  for (std::string field; std::getline(ss, field, ',');) fields.push_back(field);
  return fields;
}

// The header row of the CSV file given to `option`; CLI::ValidationError when it cannot be read.
std::vector<std::string> csv_header(std::ifstream& f, const std::string& path, const std::string& option) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) throw CLI::ValidationError(option, "'" + path + "' is not a file");
  f.open(path);
  std::string header;
  if (!f || !std::getline(f, header)) throw CLI::ValidationError(option, "cannot read '" + path + "'");
  return csv_fields(header);
}
}  // namespace

std::string tag(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

std::string case_label(double speed, double height, double climb) {
  return "V = " + tag(speed) + " m/s" + (height > 0 ? ", z/R = " + tag(height) : std::string()) +
         (climb > 0 ? ", climb " + tag(climb) + " m/s" : std::string());
}

void check_csv_columns(const std::string& path, const std::string& option, const std::vector<std::string>& columns) {
  std::ifstream f;
  const std::vector<std::string> names = csv_header(f, path, option);
  for (const std::string& c : columns)
    if (std::find(names.begin(), names.end(), c) == names.end())
      throw CLI::ValidationError(option, "'" + path + "' has no column '" + c + "' in its header row");
}

std::optional<std::vector<std::string>> csv_column(const std::string& path, const std::string& option, const std::string& column) {
  std::ifstream f;
  const std::vector<std::string> names = csv_header(f, path, option);
  const auto at = std::find(names.begin(), names.end(), column);
  if (at == names.end()) return std::nullopt;
  const auto index = static_cast<std::size_t>(at - names.begin());
  std::vector<std::string> values;
  for (std::string line; std::getline(f, line);) {
    const std::vector<std::string> fields = csv_fields(line);
    if (!fields.empty()) values.push_back(index < fields.size() ? fields[index] : std::string());
  }
  return values;
}

// Plot with Debian's python3 + matplotlib; a missing plotter is a warning, the CSV stays.
void plot(const std::string& kind, const fs::path& csv, const fs::path& png, const std::string& reference) {
  std::string args = kind + " '" + csv.string() + "' '" + png.string() + "'";
  if (!reference.empty()) args += " --reference '" + reference + "'";
  if (!run_script("plot_flight.py", args))
    std::cerr << "ship_lrm: warning: plotting failed (the message above says why; it needs Debian's python3 with matplotlib); the CSV "
              << csv << " is complete\n";
  else
    std::cout << "wrote " << png.string() << "\n";
}

void write_plane(const fs::path& dir, const std::string& stem, const lrm::DomainSlice& s, double radius, bool png) {
  const fs::path csv = dir / (stem + ".csv");
  std::ofstream f(csv);
  const bool undisturbed = !s.undisturbed.empty();
  f << "x_m,z_m,u_x_m_s,u_y_m_s,u_z_m_s,wall,rotor_radius_m";
  if (undisturbed) f << ",undisturbed_u_x_m_s,undisturbed_u_y_m_s,undisturbed_u_z_m_s";
  f << "\n" << std::setprecision(6);
  for (size_t i = 0; i < s.position.size(); ++i) {
    f << s.position[i].x() << "," << s.position[i].z() << "," << s.velocity[i].x() << "," << s.velocity[i].y() << "," << s.velocity[i].z()
      << "," << static_cast<int>(s.wall[i]) << "," << radius;
    if (undisturbed) f << "," << s.undisturbed[i].x() << "," << s.undisturbed[i].y() << "," << s.undisturbed[i].z();
    f << "\n";
  }
  f.close();
  if (!f) throw std::runtime_error("could not write " + csv.string());
  if (png) plot("plane", csv, dir / (stem + ".png"), "");
}

void add_plane_outputs(std::vector<std::string>& names, const std::string& stem) {
  names.push_back(stem + ".csv");
  names.push_back(stem + ".png");
}

}  // namespace ship_lrm::tools
