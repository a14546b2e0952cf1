// The ship approach of thesis 9.1, ROS-free (the batch path of ARCHITECTURE.md; the ROS Scenario
// nodelet drives the same class): a Bo 105 moved along a prescribed path from behind the ship to a
// hover over its flight deck, with the controls fixed at the Pitt-Peters trim for the approach's
// airspeed (a whirl tower with a fuselage, thesis 9.1), while the LRM domain around the rotor is fed
// by the ship-wake table at its faces and holds the moving ship and sea as walls. One step() is one
// coupling step of thesis 6.5 / fig. 5.5:
//   ship motion(t) -> ship walls in the LRM (re-voxelised when moved by a quarter cell)
//   wake table(t)  -> LRM faces (WakeFaceFeed)
//   flight model   -> rotor force harmonics -> LRM step(s) -> inflow -> blades advance
// Deterministic in simulated time. All positions in the wake table's mean frame (ship_motion.hpp:
// x forward, y starboard, z down, origin at the hangar-door base), which serves as the flight model's
// NED world; the undisturbed air (the table's free stream) is the flight model's wind.
#pragma once
#include <memory>
#include <string>

#include "ship_lrm/flight/helicopter.hpp"
#include "ship_lrm/flight/trim.hpp"
#include "ship_lrm/lrm/lrm_inflow.hpp"
#include "ship_lrm/lrm/ship_walls.hpp"
#include "ship_lrm/lrm/wake_feed.hpp"

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
  void validate() const;               // lbm::ConfigError naming the bad value
};

struct ApproachConfig {
  std::string table;           // the wake table (HDF5, wake_table.hpp)
  std::string inflow = "lrm";  // lrm | pitt_peters (the table's air at the hub as the wind)
  LrmConfig lrm;               // N, reach, backend; radius and density are the helicopter's
  ApproachPath path;
  double duration = 30.0;       // s (thesis 9.1)
  double startup = 5.0;         // s: the start-up period; the Delta of thesis 9.2 is taken against this time
  double trim_speed = 0;        // m/s airspeed of the fixed controls' trim; 0: |free stream| + path speed (thesis: 25.58)
  double table_offset = 0;      // s: approach t = 0 is the table's first frame plus this
  bool ship_walls = true;       // ship and sea as walls of the LRM domain
  bool fuselage = true;         // the Bo 105-like fuselage (walls.hpp) in the LRM domain (thesis fig. 9.2)
  bool wake = true;             // the table's wake at the faces; false: its free stream only (thesis appendix VIII)
  double lattice_margin = 1.3;  // lattice reference speed >= margin * (|free stream| + path speed), for the gusts
};

// What one coupling step leaves (rotor loads aerodynamic only, mr axes; coefficients as in thesis 9.2
// with the nominal rotor speed: C_T = T / (rho pi R^2 (Omega R)^2), C_M = M / (rho pi R^2 (Omega R)^2 R)).
struct ApproachSample {
  double time = 0;                                // s
  Vec3 cg = Vec3::Zero();                         // m, mean frame
  double distance = 0;                            // m behind the landing spot
  double height_above_deck = 0;                   // m, cg above the (moving) deck plane
  double speed = 0;                               // m/s relative to the ship
  double thrust = 0, ct = 0, cmx = 0, cmy = 0;    // N, -, -, -
  double main_power = 0;                          // W
  Vec3 inflow_mean = Vec3::Zero();                // m/s, mr axes, relative to the rotor frame
  double ship_heave = 0, ship_pitch = 0;          // m (up), rad (bow up)
  std::size_t wall_cells = 0, voxelisations = 0;  // LRM
  std::size_t face_refreshes = 0;
};

class ShipApproach {
 public:
  // Opens the table, rebuilds its ship and motion (from the table's attributes), trims the helicopter
  // with Pitt-Peters, builds the LRM domain. lbm::ConfigError or wake::TableError for bad input: a
  // table too short for the duration, a ship the table cannot name, a path that leaves the table, ...
  ShipApproach(const ApproachConfig& cfg, const flight::HelicopterParameters& params);
  void step();  // one coupling step
  bool done() const;
  double time() const { return heli_->time(); }
  double time_step() const { return heli_->time_step(); }
  const ApproachSample& sample() const { return sample_; }
  const flight::TrimResult& trim() const { return trim_; }
  const ApproachConfig& config() const { return cfg_; }
  const wake::WakeTableInfo& table_info() const { return table_->info(); }
  flight::Helicopter& helicopter() { return *heli_; }
  LrmDomain* lrm_domain() { return lrm_ ? &lrm_->domain() : nullptr; }
  // The domain's pose at approach time t (also the ROS layer's tf).
  DomainPose domain_pose(double t) const;
  // Wall-clock seconds spent so far in step() (the coupled step, for t_clock / t_sim).
  double wall_seconds() const { return wall_seconds_; }

 private:
  void place(double t, bool start);  // path, walls, faces for time t; start: reset the helicopter there
  void record();
  ApproachConfig cfg_;
  std::shared_ptr<wake::WakeTable> table_;
  std::shared_ptr<const wake::ShipGeometry> ship_;
  std::shared_ptr<const wake::ShipMotion> motion_;
  Vec3 spot_ = Vec3::Zero();  // landing spot, ship frame
  flight::TrimResult trim_;
  Eigen::Quaterniond attitude_;  // body -> mean frame, held
  std::unique_ptr<flight::Helicopter> heli_;
  LrmInflow* lrm_ = nullptr;  // owned by heli_
  std::unique_ptr<ShipInDomain> walls_;
  std::unique_ptr<WakeFaceFeed> feed_;
  std::vector<double> hub_xyz_;
  std::vector<wake::WakeSample> hub_air_;
  ApproachSample sample_;
  double wall_seconds_ = 0;
};

}  // namespace ship_lrm::lrm
