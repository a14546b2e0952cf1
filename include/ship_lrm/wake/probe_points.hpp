// Probe points of a ship-wake run: where they are read from and the frames they may be given in.
// The ship frame (ship_geometry.hpp): origin on the centreline at the bottom of the hangar door, x
// forward, y starboard, z down. The wind-tunnel frame of the NRC measurements (Bludau 2024, 7.1; our
// reading of its "coordinate system 2"): the same origin, x aft along the deck, y starboard, z up.
#pragma once
#include <array>
#include <string>
#include <vector>

namespace ship_lrm::wake {

enum class ProbeFrame { Ship, Tunnel };
ProbeFrame parse_probe_frame(const std::string& name);  // "ship" or "tunnel"; ConfigError otherwise
std::string to_string(ProbeFrame f);

// A point given in `frame` at a geometry `factor` times the run's (e.g. model-scale probes on a
// full-scale run: factor 50) into the run's ship frame, and back.
std::array<double, 3> to_ship_frame(const std::array<double, 3>& p, ProbeFrame frame, double factor = 1.0);
std::array<double, 3> from_ship_frame(const std::array<double, 3>& p, ProbeFrame frame, double factor = 1.0);

// Probe points from a CSV file: one point per row, x,y,z in metres; a first row of names, blank lines
// and lines starting with '#' are skipped. ConfigError naming the file and line for anything else.
std::vector<std::array<double, 3>> read_probe_csv(const std::string& path);

}  // namespace ship_lrm::wake
