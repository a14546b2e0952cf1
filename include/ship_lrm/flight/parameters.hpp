// Bo 105 (or any single-main-rotor helicopter) parameters of the blade-element flight model, loaded
// from YAML (config/bo105.yaml lists each value's source). All SI, angles stored in radians.
#pragma once

#include <Eigen/Core>
#include <stdexcept>
#include <string>
#include <vector>

#include "ship_lrm/flight/airfoil_table.hpp"

namespace ship_lrm::flight {

// A missing, malformed or out-of-range parameter; what() names the field and the file.
class ParameterError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct MassParameters {
  double mass = 0, ixx = 0, iyy = 0, izz = 0, ixz = 0, gravity = 9.80665;
};

struct MainRotorParameters {
  Eigen::Vector3d hub_position = Eigen::Vector3d::Zero();  // m, body FRD from cg
  double shaft_tilt = 0;                                   // rad, forward
  bool clockwise = false;                                  // seen from above
  int blades = 4;
  double radius = 0, chord = 0, twist = 0, twist_reference = 0.75, tip_loss = 1.0;
  std::vector<double> stations;   // r/R of the element edges
  double rotor_speed = 0;         // rad/s nominal
  double blade_flap_inertia = 0;  // kg m^2 about the rotor centre
  double flap_frequency_ratio = 1, hinge_offset = 0, lag_frequency_ratio = 0.65, lag_damping_ratio = 0.05;
  double rotor_inertia = 0;  // kg m^2
  AirfoilTable polar;
};

struct TailRotorParameters {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  double radius = 0, solidity = 0, lift_slope = 0, profile_drag = 0, gear_ratio = 0;
};

struct FuselageParameters {
  double drag_area = 0, drag_area_per_rad2 = 0, lift_area_per_rad = 0, side_area_per_rad = 0;
  double pitch_volume_per_rad = 0, yaw_volume_per_rad = 0;
  double vertical_drag_area = 0;  // m^2, plan area times drag coefficient in the rotor wake
  double wake_factor = 0;         // wake velocity at the airframe / mean induced velocity at the disk
};

struct SurfaceParameters {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  double area = 0, lift_slope = 0, incidence = 0, downwash_factor = 0;
};

struct EngineParameters {
  double max_power = 0, time_constant = 0.3, governor_gain = 4, governor_integral = 2;
  double load_anticipation = 0;  // 0..1: share of the load change fed forward to the engine
};

struct ControlParameters {
  double collective_min = 0, collective_max = 0;  // rad at 0 % / 100 %
  double longitudinal = 0, lateral = 0;           // rad at full deflection from centre
  double tail_min = 0, tail_max = 0;              // rad at 0 % / 100 % pedal
};

// Where the helicopter touches a surface it lands on (a free flight ends there: no contact dynamics).
struct LandingGearParameters {
  std::vector<Eigen::Vector3d> contact_points;  // m, body FRD from the cg; empty: contact not detected
};

struct HelicopterParameters {
  std::string source;  // file it came from
  MassParameters mass;
  double density = 1.225, speed_of_sound = 340.3;
  MainRotorParameters main_rotor;
  TailRotorParameters tail_rotor;
  FuselageParameters fuselage;
  SurfaceParameters stabiliser, fin;
  EngineParameters engine;
  ControlParameters controls;
  LandingGearParameters landing_gear;  // optional in the file
  double time_step = 0.00180352;
  int blade_substeps = 1;
};

// Loads and checks a parameter file; throws ParameterError naming field and file.
HelicopterParameters load_helicopter_parameters(const std::string& path);

// The Bo 105 file shipped with the package (config/bo105.yaml), found via SHIP_LRM_CONFIG_DIR
// (environment) or the source tree's config/ directory.
std::string default_config_directory();
// A directory shipped with the package: $env_var when set, else <source tree>/subdir (e.g. scripts).
std::string shipped_directory(const char* env_var, const char* subdir);
HelicopterParameters load_default_bo105();

}  // namespace ship_lrm::flight
