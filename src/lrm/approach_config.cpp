// The ship approach's configuration and what both its sides derive from it (see approach_config.hpp).
#include "ship_lrm/lrm/approach_config.hpp"

#include <cmath>
#include <sstream>

namespace ship_lrm::lrm {
namespace {
std::string num(double v) {
  std::ostringstream o;
  o << v;
  return o.str();
}
}  // namespace

double ApproachPath::speed_at(double t) const {
  if (t <= decelerate_at) return speed;
  if (t >= hover_at) return 0.0;
  return speed * (hover_at - t) / (hover_at - decelerate_at);
}

double ApproachPath::distance_at(double t) const {
  const double cruise = speed * std::min(std::max(t, 0.0), decelerate_at);
  const double s = std::min(std::max(t, decelerate_at), hover_at) - decelerate_at;  // time into the deceleration
  const double braking = hover_at > decelerate_at ? speed * (s - 0.5 * s * s / (hover_at - decelerate_at)) : 0.0;
  return start_distance - cruise - braking;
}

void ApproachPath::validate() const {
  if (!std::isfinite(start_distance)) throw ConfigError("approach: the start distance must be finite");
  if (!(height > 0) || !std::isfinite(height)) throw ConfigError("approach: the height above the deck must be > 0 m, got " + num(height));
  if (!(speed >= 0) || !std::isfinite(speed)) throw ConfigError("approach: the speed must be >= 0 m/s, got " + num(speed));
  if (!std::isfinite(lateral)) throw ConfigError("approach: the lateral offset must be finite");
  if (!(decelerate_at >= 0) || !(hover_at >= decelerate_at) || !std::isfinite(hover_at))
    throw ConfigError("approach: need 0 <= decelerate-at <= hover-at, got " + num(decelerate_at) + " and " + num(hover_at));
}

void validate(const ApproachConfig& cfg) {
  cfg.path.validate();
  if (!(cfg.duration > 0) || !std::isfinite(cfg.duration)) throw ConfigError("approach: the duration must be > 0 s");
  if (!(cfg.startup >= 0) || !(cfg.startup < cfg.duration))
    throw ConfigError("approach: the start-up must lie in [0, duration), got " + num(cfg.startup));
  if (cfg.inflow != "lrm" && cfg.inflow != "pitt_peters")
    throw ConfigError("approach: inflow must be 'lrm' or 'pitt_peters', got '" + cfg.inflow + "'");
  if (!(cfg.table_offset >= 0) || !std::isfinite(cfg.table_offset)) throw ConfigError("approach: the table offset must be >= 0 s");
  if (!(cfg.trim_speed >= 0) || !std::isfinite(cfg.trim_speed)) throw ConfigError("approach: the trim speed must be >= 0 m/s");
  if (!(cfg.lattice_margin >= 1) || !std::isfinite(cfg.lattice_margin))
    throw ConfigError("approach: the lattice margin must be >= 1, got " + num(cfg.lattice_margin));
}

std::shared_ptr<wake::WakeTable> open_approach_table(const ApproachConfig& cfg) {
  validate(cfg);
  auto table = std::make_shared<wake::WakeTable>(cfg.table);
  check_approach_table(cfg, *table);
  return table;
}

void check_approach_table(const ApproachConfig& cfg, const wake::WakeTable& table) {
  const wake::WakeTableInfo& info = table.info();
  if (info.scale != "full")
    throw ConfigError("approach: the wake table '" + cfg.table + "' is of a " + info.scale +
                      "-scale ship; the Bo 105 needs a full-scale table (ship_lrm wake --scale full)");
  const double need = info.start_time + cfg.table_offset + cfg.duration;
  if (need > info.end_time() + 1e-6)
    throw ConfigError("approach: the wake table '" + cfg.table + "' covers " + num(info.end_time() - info.start_time) +
                      " s; the approach needs " + num(cfg.table_offset + cfg.duration) +
                      " s (shorten --duration or make a longer table with ship_lrm wake --duration)");
}

ApproachShip approach_ship(const ApproachConfig& cfg, const wake::WakeTableInfo& info) {
  ApproachShip s;
  try {
    s.geometry = wake::make_ship(info.ship, info.scale);
    s.motion = wake::make_motion(info.motion, wake::ship_scale(info.scale), wake::motion_centre(s.geometry->datum()));
  } catch (const std::exception& e) {
    throw ConfigError("approach: cannot rebuild the ship of wake table '" + cfg.table + "' (ship '" + info.ship + "', motion '" +
                      info.motion + "'): " + e.what());
  }
  s.spot = wake::landing_spot(s.geometry->datum());
  return s;
}

Vec3 free_stream(const wake::WakeTableInfo& info) { return Vec3(info.free_stream[0], info.free_stream[1], info.free_stream[2]); }

LrmConfig approach_lrm_config(const ApproachConfig& cfg, const flight::HelicopterParameters& params, const wake::WakeTableInfo& info) {
  LrmConfig c = cfg.lrm;
  c.radius = params.main_rotor.radius;
  c.density = params.density;
  return config_for_stream(c, cfg.lattice_margin * (free_stream(info).norm() + cfg.path.speed));
}

}  // namespace ship_lrm::lrm
