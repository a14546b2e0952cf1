// Loading and checking of the helicopter parameter file (config/bo105.yaml).
#include "ship_lrm/flight/parameters.hpp"

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>

namespace ship_lrm::flight {
namespace {

constexpr double kDeg = M_PI / 180.0;

class Reader {
 public:
  explicit Reader(std::string path) : path_(std::move(path)) {
    std::error_code ec;
    if (std::filesystem::is_directory(path_, ec)) throw ParameterError(path_ + ": is a directory, not a parameter file");
    try {
      root_ = YAML::LoadFile(path_);
    } catch (const YAML::BadFile&) {
      throw ParameterError(path_ + ": cannot open the parameter file");
    } catch (const YAML::Exception& e) {
      throw ParameterError(path_ + ": not valid YAML: " + e.what());
    }
  }

  YAML::Node node(const std::string& dotted) const {
    YAML::Node n = YAML::Clone(root_);
    std::stringstream ss(dotted);
    std::string part;
    while (std::getline(ss, part, '.')) {
      if (!n.IsMap() || !n[part]) throw ParameterError(path_ + ": field '" + dotted + "' is missing");
      n = n[part];
    }
    return n;
  }

  // A number in [lo, hi] (inclusive).
  double number(const std::string& field, double lo, double hi) const {
    double v;
    try {
      v = node(field).as<double>();
    } catch (const YAML::Exception&) {
      throw ParameterError(path_ + ": field '" + field + "' must be a number");
    }
    if (!std::isfinite(v) || v < lo || v > hi) {
      std::ostringstream os;
      os << path_ << ": field '" << field << "' = " << v << " is out of range [" << lo << ", " << hi << "]";
      throw ParameterError(os.str());
    }
    return v;
  }

  std::vector<double> numbers(const std::string& field, size_t count_min, size_t count_max, double lo, double hi) const {
    std::vector<double> v;
    try {
      v = node(field).as<std::vector<double>>();
    } catch (const YAML::Exception&) {
      throw ParameterError(path_ + ": field '" + field + "' must be a list of numbers");
    }
    if (v.size() < count_min || v.size() > count_max) {
      std::ostringstream os;
      os << path_ << ": field '" << field << "' needs " << count_min << (count_min == count_max ? "" : " or more") << " values, has "
         << v.size();
      throw ParameterError(os.str());
    }
    for (double x : v)
      if (!std::isfinite(x) || x < lo || x > hi) {
        std::ostringstream os;
        os << path_ << ": field '" << field << "' has value " << x << " out of range [" << lo << ", " << hi << "]";
        throw ParameterError(os.str());
      }
    return v;
  }

  Eigen::Vector3d vector3(const std::string& field, double lim) const {
    const auto v = numbers(field, 3, 3, -lim, lim);
    return {v[0], v[1], v[2]};
  }

  std::string text(const std::string& field) const {
    try {
      return node(field).as<std::string>();
    } catch (const YAML::Exception&) {
      throw ParameterError(path_ + ": field '" + field + "' must be text");
    }
  }

  // Whether the (dotted) field is there, for optional sections.
  bool has(const std::string& dotted) const {
    YAML::Node n = YAML::Clone(root_);
    std::stringstream ss(dotted);
    std::string part;
    while (std::getline(ss, part, '.')) {
      if (!n.IsMap() || !n[part]) return false;
      n = n[part];
    }
    return true;
  }

  const std::string& path() const { return path_; }

 private:
  std::string path_;
  YAML::Node root_;
};

}  // namespace

HelicopterParameters load_helicopter_parameters(const std::string& path) {
  const Reader r(path);
  HelicopterParameters p;
  p.source = path;
  auto& m = p.mass;
  m.mass = r.number("mass.mass", 1.0, 1e6);
  m.ixx = r.number("mass.ixx", 1e-3, 1e8);
  m.iyy = r.number("mass.iyy", 1e-3, 1e8);
  m.izz = r.number("mass.izz", 1e-3, 1e8);
  m.ixz = r.number("mass.ixz", -1e8, 1e8);
  if (m.ixz * m.ixz >= m.ixx * m.izz) throw ParameterError(path + ": field 'mass.ixz' makes the inertia tensor not positive definite");
  m.gravity = r.number("mass.gravity", 0.0, 100.0);
  p.density = r.number("atmosphere.density", 0.01, 5.0);
  p.speed_of_sound = r.number("atmosphere.speed_of_sound", 100.0, 1000.0);

  auto& mr = p.main_rotor;
  mr.hub_position = r.vector3("main_rotor.hub_position", 50.0);
  mr.shaft_tilt = r.number("main_rotor.shaft_tilt", -20.0, 20.0) * kDeg;
  const std::string rot = r.text("main_rotor.rotation");
  if (rot != "clockwise" && rot != "counterclockwise")
    throw ParameterError(path + ": field 'main_rotor.rotation' must be 'clockwise' or 'counterclockwise', not '" + rot + "'");
  mr.clockwise = rot == "clockwise";
  mr.blades = static_cast<int>(r.number("main_rotor.blades", 2, 8));
  if (mr.blades != r.number("main_rotor.blades", 2, 8)) throw ParameterError(path + ": field 'main_rotor.blades' must be a whole number");
  mr.radius = r.number("main_rotor.radius", 0.1, 50.0);
  mr.chord = r.number("main_rotor.chord", 0.01, 0.3 * mr.radius);
  mr.twist = r.number("main_rotor.twist", -40.0, 40.0) * kDeg;
  mr.twist_reference = r.number("main_rotor.twist_reference", 0.0, 1.0);
  mr.tip_loss = r.number("main_rotor.tip_loss", 0.8, 1.0);
  mr.stations = r.numbers("main_rotor.stations", 2, 64, 0.0, 1.0);
  for (size_t i = 1; i < mr.stations.size(); ++i)
    if (mr.stations[i] <= mr.stations[i - 1]) throw ParameterError(path + ": field 'main_rotor.stations' must be strictly increasing");
  mr.rotor_speed = r.number("main_rotor.rotor_speed", 1.0, 1e4);
  mr.blade_flap_inertia = r.number("main_rotor.blade_flap_inertia", 1e-6, 1e7);
  mr.flap_frequency_ratio = r.number("main_rotor.flap_frequency_ratio", 1.0, 3.0);
  mr.hinge_offset = r.number("main_rotor.hinge_offset", 0.0, 0.3 * mr.radius);
  if (mr.hinge_offset >= mr.stations.front() * mr.radius)
    throw ParameterError(path + ": field 'main_rotor.hinge_offset' must lie inboard of the first station");
  mr.lag_frequency_ratio = r.number("main_rotor.lag_frequency_ratio", 0.05, 3.0);
  mr.lag_damping_ratio = r.number("main_rotor.lag_damping_ratio", 0.0, 2.0);
  mr.rotor_inertia = r.number("main_rotor.rotor_inertia", 1e-6, 1e8);
  const std::string polar = r.text("main_rotor.polar");
  const std::filesystem::path polar_path = std::filesystem::path(path).parent_path() / polar;
  mr.polar = load_airfoil_table(polar_path.string());

  auto& tr = p.tail_rotor;
  tr.position = r.vector3("tail_rotor.position", 100.0);
  tr.radius = r.number("tail_rotor.radius", 0.01, 20.0);
  tr.solidity = r.number("tail_rotor.solidity", 0.001, 1.0);
  tr.lift_slope = r.number("tail_rotor.lift_slope", 0.1, 10.0);
  tr.profile_drag = r.number("tail_rotor.profile_drag", 0.0, 0.2);
  tr.gear_ratio = r.number("tail_rotor.gear_ratio", 0.1, 50.0);

  auto& f = p.fuselage;
  f.drag_area = r.number("fuselage.drag_area", 0.0, 100.0);
  f.drag_area_per_rad2 = r.number("fuselage.drag_area_per_rad2", 0.0, 1000.0);
  f.lift_area_per_rad = r.number("fuselage.lift_area_per_rad", -100.0, 100.0);
  f.side_area_per_rad = r.number("fuselage.side_area_per_rad", 0.0, 1000.0);
  f.pitch_volume_per_rad = r.number("fuselage.pitch_volume_per_rad", -1000.0, 1000.0);
  f.yaw_volume_per_rad = r.number("fuselage.yaw_volume_per_rad", -1000.0, 1000.0);
  f.vertical_drag_area = r.number("fuselage.vertical_drag_area", 0.0, 1000.0);
  f.wake_factor = r.number("fuselage.wake_factor", 0.0, 2.0);

  const auto surface = [&](const std::string& key, bool downwash) {
    SurfaceParameters s;
    s.position = r.vector3(key + ".position", 100.0);
    s.area = r.number(key + ".area", 0.0, 1000.0);
    s.lift_slope = r.number(key + ".lift_slope", 0.0, 10.0);
    s.incidence = r.number(key + ".incidence", -30.0, 30.0) * kDeg;
    s.downwash_factor = downwash ? r.number(key + ".downwash_factor", 0.0, 2.0) : 0.0;
    return s;
  };
  p.stabiliser = surface("horizontal_stabiliser", true);
  p.fin = surface("fin", false);

  auto& e = p.engine;
  e.max_power = r.number("engine.max_power", 1.0, 1e8);
  e.time_constant = r.number("engine.time_constant", 0.001, 10.0);
  e.governor_gain = r.number("engine.governor_gain", 0.0, 1000.0);
  e.governor_integral = r.number("engine.governor_integral", 0.0, 1000.0);
  e.load_anticipation = r.number("engine.load_anticipation", 0.0, 1.0);

  auto& c = p.controls;
  const auto coll = r.numbers("controls.collective_pitch", 2, 2, -30.0, 40.0);
  c.collective_min = coll[0] * kDeg;
  c.collective_max = coll[1] * kDeg;
  if (c.collective_max <= c.collective_min) throw ParameterError(path + ": field 'controls.collective_pitch' must be [low, high]");
  c.longitudinal = r.number("controls.longitudinal_cyclic", 0.1, 30.0) * kDeg;
  c.lateral = r.number("controls.lateral_cyclic", 0.1, 30.0) * kDeg;
  const auto tail = r.numbers("controls.tail_rotor_pitch", 2, 2, -45.0, 45.0);
  c.tail_min = tail[0] * kDeg;
  c.tail_max = tail[1] * kDeg;
  if (c.tail_max <= c.tail_min) throw ParameterError(path + ": field 'controls.tail_rotor_pitch' must be [low, high]");

  if (r.has("landing_gear")) {
    // skids: two runners `skid_track` apart, from `skid_rear` to `skid_front` (x from the cg), at
    // `skid_depth` below the cg; their four ends are the contact points
    const double front = r.number("landing_gear.skid_front", -20.0, 20.0);
    const double rear = r.number("landing_gear.skid_rear", -20.0, 20.0);
    if (rear >= front) throw ParameterError(path + ": field 'landing_gear.skid_rear' must lie aft of 'landing_gear.skid_front'");
    const double half_track = 0.5 * r.number("landing_gear.skid_track", 0.0, 20.0);
    const double depth = r.number("landing_gear.skid_depth", 0.0, 20.0);
    for (double x : {front, rear})
      for (double y : {-half_track, half_track}) p.landing_gear.contact_points.emplace_back(x, y, depth);
  }

  p.time_step = r.number("simulation.time_step", 1e-5, 0.05);
  const double sub = r.number("simulation.blade_substeps", 1, 64);
  p.blade_substeps = static_cast<int>(sub);
  if (p.blade_substeps != sub) throw ParameterError(path + ": field 'simulation.blade_substeps' must be a whole number");
  return p;
}

std::string shipped_directory(const char* env_var, const char* subdir) {
  if (const char* env = std::getenv(env_var)) return env;
#ifdef SHIP_LRM_SOURCE_DIR
  return std::string(SHIP_LRM_SOURCE_DIR) + "/" + subdir;
#else
  return subdir;
#endif
}

std::string default_config_directory() { return shipped_directory("SHIP_LRM_CONFIG_DIR", "config"); }

HelicopterParameters load_default_bo105() { return load_helicopter_parameters(default_config_directory() + "/bo105.yaml"); }

}  // namespace ship_lrm::flight
