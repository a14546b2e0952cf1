// What configures the ship approach of thesis 9.1 (approach.hpp), and what its flight side and its
// fluid side (approach_fluid.hpp) both derive from it, each once: the wake table checked for the
// run, the ship and its motion rebuilt from the table's attributes, the LRM's lattice settings.
// The ROS nodelets build the same ApproachConfig from their parameters, so all paths agree.
#pragma once
#include <memory>
#include <string>

#include "ship_lrm/flight/parameters.hpp"
#include "ship_lrm/lrm/domain.hpp"
#include "ship_lrm/wake/ship_geometry.hpp"
#include "ship_lrm/wake/ship_motion.hpp"
#include "ship_lrm/wake/wake_table.hpp"

namespace ship_lrm::lrm {

// The path of thesis 9.1 (fig. 9.1): cg on the centreline `height` above the deck (constant above the
// mean sea level, so the height above the moving deck varies), from `start_distance` behind the
// landing spot towards the bow at `speed` relative to the ship, decelerating linearly from
// `decelerate_at` to a hover from `hover_at` on. With the thesis' numbers the hover is 9.5 m behind
// the landing spot (97 - 5 * 17 - 2.5), over the deck of ship_geometry.cpp's destroyer.
struct ApproachPath {
  double start_distance = 97.0;  // m behind the landing spot at t = 0
  double height = 8.0;           // m, cg above the deck level (z = 0 of the ship frame)
  double lateral = 0.0;          // m, starboard of the centreline
  double speed = 5.0;            // m/s towards the bow, relative to the ship
  double decelerate_at = 17.0;   // s
  double hover_at = 18.0;        // s
  double speed_at(double t) const;
  double distance_at(double t) const;  // m behind the landing spot (negative: ahead of it)
  void validate() const;               // ConfigError naming the bad value
};

struct ApproachConfig {
  std::string table;           // the wake table (HDF5, wake_table.hpp)
  std::string inflow = "lrm";  // lrm | pitt_peters (the table's air at the hub as the wind)
  LrmConfig lrm;               // N, reach, backend; radius and density are the helicopter's
  ApproachPath path;
  double duration = 30.0;   // s (thesis 9.1)
  double startup = 5.0;     // s: the start-up period; the Delta of thesis 9.2 is taken against this time
  double trim_speed = 0;    // m/s airspeed of the fixed controls' trim; 0: |free stream| + path speed (thesis: 25.58)
  double table_offset = 0;  // s: approach t = 0 is the table's first frame plus this
  bool ship_walls = true;   // ship and sea as walls of the LRM domain
  bool fuselage = true;     // the Bo 105-like fuselage (walls.hpp) in the LRM domain (thesis fig. 9.2)
  bool wake = true;         // the table's wake at the faces; false: its free stream only (thesis appendix VIII)
  // false: the rotor's forces are not put on the LRM's fluid, so the domain recomputes the ship's wake
  // alone from the table at its faces (to compare with the table inside the domain). A diagnostic: the
  // rotor then flies without its own induced flow.
  bool rotor_forces_on_fluid = true;
  double lattice_margin = 1.3;  // lattice reference speed >= margin * (|free stream| + path speed), for the gusts
  // false: the airframe is held on the path (thesis 9.1's whirl tower with a fuselage). true: it is
  // held there only during the start-up (the blades and the LRM's wake settle, and the controls are
  // re-trimmed for this inflow model), then flies freely (6-DOF) from where the path had brought it; the
  // controls are then the caller's (a pilot), and the run ends early where the landing gear touches
  // the ship or the sea.
  bool free_flight = false;
};

// Checks the configuration (ConfigError naming the bad value) and opens its table: full scale,
// long enough for table_offset + duration (ConfigError / wake::TableError otherwise).
void validate(const ApproachConfig& cfg);
std::shared_ptr<wake::WakeTable> open_approach_table(const ApproachConfig& cfg);
// The same checks for a table opened otherwise (served by another process): full scale, long enough.
void check_approach_table(const ApproachConfig& cfg, const wake::WakeTable& table);

// The table's ship, its motion and the landing spot (ship frame), rebuilt from the table's attributes.
struct ApproachShip {
  std::shared_ptr<const wake::ShipGeometry> geometry;
  std::shared_ptr<const wake::ShipMotion> motion;
  Vec3 spot = Vec3::Zero();
};
ApproachShip approach_ship(const ApproachConfig& cfg, const wake::WakeTableInfo& info);

// The table's free stream (the undisturbed air, mean frame).
Vec3 free_stream(const wake::WakeTableInfo& info);

// The LRM's settings for this approach: the helicopter's radius and density, the lattice reference
// speed lattice_margin * (|free stream| + path speed).
LrmConfig approach_lrm_config(const ApproachConfig& cfg, const flight::HelicopterParameters& params, const wake::WakeTableInfo& info);

}  // namespace ship_lrm::lrm
