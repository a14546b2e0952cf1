// The ship approach of thesis 9.1, ROS-free (the batch path; the ROS Scenario
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
#include <chrono>
#include <memory>
#include <optional>
#include <string>

#include "ship_lrm/flight/helicopter.hpp"
#include "ship_lrm/flight/trim.hpp"
#include "ship_lrm/lrm/approach_config.hpp"
#include "ship_lrm/lrm/approach_fluid.hpp"
#include "ship_lrm/lrm/inflow_link.hpp"
#include "ship_lrm/lrm/realtime_inflow.hpp"

namespace ship_lrm::lrm {

// What one coupling step leaves (rotor loads aerodynamic only, mr axes; coefficients as in thesis 9.2
// with the nominal rotor speed: C_T = T / (rho pi R^2 (Omega R)^2), C_M = M / (rho pi R^2 (Omega R)^2 R)).
struct ApproachSample {
  double time = 0;                                // s
  Vec3 cg = Vec3::Zero();                         // m, mean frame
  double distance = 0;                            // m behind the landing spot
  double height_above_deck = 0;                   // m, cg above the (moving) deck plane
  double speed = 0;                               // m/s towards the bow, relative to the mean frame
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
  // with Pitt-Peters. With LRM inflow the fluid side (approach_fluid.hpp) answers through `link`; no
  // link: an ApproachFluid in this process (the batch path). ConfigError or wake::TableError for
  // bad input: a table too short for the duration, a ship the table cannot name, a bad path, ...
  // realtime: for runs paced to the wall clock, the LRM side runs in its own thread with firm
  // deadlines (RealTimeInflow around the link; a late inflow is replaced by Pitt-Peters for that
  // step); give each step its deadline with set_deadline(). Not deterministic; nullopt: simulated time.
  ShipApproach(const ApproachConfig& cfg, const flight::HelicopterParameters& params, std::shared_ptr<InflowLink> link = nullptr,
               std::optional<RealTimeMode> realtime = std::nullopt);
  void step();  // one coupling step
  // Real time: the wall-clock time by which the next step's inflow must be there (no-op otherwise).
  void set_deadline(std::chrono::steady_clock::time_point due) {
    if (realtime_) realtime_->set_deadline(due);
  }
  // Real time: the deadline statistics, else nullptr.
  const RealTimeInflow* realtime_inflow() const { return realtime_; }
  // The duration is over, or (free flight) the landing gear touched the ship or the sea, or the LRM's
  // ship or sea walls reached the rotor disk (a rotor strike; the last step is not recorded).
  bool done() const;
  // Free flight: whether the airframe flies now (it is held on the path during the start-up).
  bool released() const;
  // Free flight: how the run ended early ("" while it goes on, or when it ran its duration).
  const std::string& end_reason() const { return end_reason_; }
  double time() const { return heli_->time(); }
  double time_step() const { return heli_->time_step(); }
  const ApproachSample& sample() const { return sample_; }
  // The Pitt-Peters trim of the fixed controls; in free flight, its controls as the start-up has
  // re-trimmed them for this inflow model (the pilot's stick centre after the release).
  const flight::TrimResult& trim() const { return trim_; }
  const ApproachConfig& config() const { return cfg_; }
  const wake::WakeTableInfo& table_info() const { return table_->info(); }
  flight::Helicopter& helicopter() { return *heli_; }
  const flight::Helicopter& helicopter() const { return *heli_; }
  // The LRM domain when it runs in this process (batch path), else nullptr.
  LrmDomain* lrm_domain() { return fluid_ ? &fluid_->domain() : nullptr; }
  // LBM steps the real-time LRM dropped to catch up (ApproachFluid::set_catch_up_limit); read it
  // when the run is over (the LRM thread owns the domain while it runs).
  long dropped_lrm_steps() const { return fluid_ ? fluid_->dropped_steps() : 0; }
  // The LRM side's counts as of the last request it served (any thread), nullopt without an LRM here.
  std::optional<ApproachFluid::Counts> fluid_counts() const {
    return fluid_ ? std::optional<ApproachFluid::Counts>(fluid_->counts()) : std::nullopt;
  }
  // With LRM inflow: the flight side's end of the link (whether it fell back to Pitt-Peters), else
  // nullptr. In real time it runs in the LRM thread: read only lost(), lost_reason() (once lost) and
  // fallback_calls() from here.
  const LinkedInflow* linked_inflow() const { return linked_; }
  // The domain's pose on the path at approach time t (held flight), and the table's time then.
  DomainPose domain_pose(double t) const;
  // The domain's pose where the rotor of `state` is (free flight: the helicopter's own pose).
  DomainPose domain_pose(const rotor::RotorDiskState& state) const;
  double table_time(double t) const { return table_->info().start_time + cfg_.table_offset + t; }
  // The ship's placement (ship frame <-> mean frame) at approach time t.
  wake::ShipPlacement ship_placement(double t) const { return ship_.motion->placement(table_time(t)); }
  // Wall-clock seconds spent so far in step() (the coupled step, for t_clock / t_sim).
  double wall_seconds() const { return wall_seconds_; }

 private:
  // Walls and faces for time t where the helicopter is: on the path (start: reset it there), or where
  // it flew to (free flight after the start-up: on_path false).
  void place(double t, bool start, bool on_path);
  void record();
  void check_contact();  // free flight: ends the run where a landing-gear point touches ship or sea
  // Free flight, during the start-up: once per rotor revolution, the four controls take a Newton step
  // (with the Pitt-Peters trim's Jacobian) against the revolution-mean heave, roll, pitch and yaw
  // accelerations the held body would have with this inflow model (the Pitt-Peters trim's controls are
  // not a trim with the LRM's inflow), so that the release is trimmed but for surge and sway.
  void trim_controls();
  Eigen::Matrix<double, 6, 1> residual_sum_ = Eigen::Matrix<double, 6, 1>::Zero();
  double residual_time_ = 0;
  ApproachConfig cfg_;
  std::shared_ptr<wake::WakeTable> table_;
  ApproachShip ship_;
  flight::TrimResult trim_;
  Eigen::Quaterniond attitude_;  // body -> mean frame, held
  std::unique_ptr<flight::Helicopter> heli_;
  std::shared_ptr<ApproachFluid> fluid_;  // batch path
  LinkedInflow* linked_ = nullptr;        // owned by heli_ (or by realtime_)
  RealTimeInflow* realtime_ = nullptr;    // owned by heli_
  std::vector<double> hub_xyz_;
  std::vector<wake::WakeSample> hub_air_;
  ApproachSample sample_;
  double wall_seconds_ = 0;
  std::string end_reason_;
};

}  // namespace ship_lrm::lrm
