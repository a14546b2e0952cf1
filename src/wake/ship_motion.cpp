// Ship motion (see ship_motion.hpp).
#include "ship_lrm/wake/ship_motion.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

namespace ship_lrm::wake {

Mat3 ShipMotion::rotation(const ShipPose& s) {
  // roll about x (starboard down positive), then pitch about y (bow up positive): the Euler angles of
  // FRD axes with zero yaw
  return (Eigen::AngleAxisd(s.pitch, Vec3::UnitY()) * Eigen::AngleAxisd(s.roll, Vec3::UnitX())).toRotationMatrix();
}

ShipPlacement ShipMotion::placement(double t) const {
  const ShipPose s = pose(t);
  return {rotation(s), centre_, s.heave};
}

Vec3 ShipMotion::position(const Vec3& p, double t) const { return placement(t).to_mean(p); }

Vec3 ShipMotion::omega(double t) const {
  const ShipPose s = pose(t);
  // R = R_y(pitch) R_x(roll): omega = pitch_rate e_y + R_y(pitch) roll_rate e_x
  return s.pitch_rate * Vec3::UnitY() + Eigen::AngleAxisd(s.pitch, Vec3::UnitY()) * (s.roll_rate * Vec3::UnitX());
}

Vec3 ShipMotion::centre_velocity(double t) const { return -pose(t).heave_rate * Vec3::UnitZ(); }

Vec3 ShipMotion::velocity(const Vec3& p, double t) const {
  return centre_velocity(t) + omega(t).cross(position(p, t) - position(centre_, t));
}

SinusoidalMotion::SinusoidalMotion(std::string name, const Params& p, const Vec3& centre)
    : ShipMotion(centre), name_(std::move(name)), p_(p) {
  if (!(p.frequency > 0) || !std::isfinite(p.frequency)) throw MotionError("ship motion: the frequency must be > 0 Hz");
  for (double v : {p.heave, p.roll, p.pitch, p.heave_phase, p.roll_phase, p.pitch_phase})
    if (!std::isfinite(v)) throw MotionError("ship motion: amplitudes and phases must be finite");
  if (std::abs(p.roll) > 0.8 || std::abs(p.pitch) > 0.8) throw MotionError("ship motion: roll or pitch amplitude beyond 45 deg");
}

ShipPose SinusoidalMotion::pose(double t) const {
  const double w = 2 * M_PI * p_.frequency;
  ShipPose s;
  s.heave = p_.heave * std::sin(w * t + p_.heave_phase);
  s.roll = p_.roll * std::sin(w * t + p_.roll_phase);
  s.pitch = p_.pitch * std::sin(w * t + p_.pitch_phase);
  s.heave_rate = p_.heave * w * std::cos(w * t + p_.heave_phase);
  s.roll_rate = p_.roll * w * std::cos(w * t + p_.roll_phase);
  s.pitch_rate = p_.pitch * w * std::cos(w * t + p_.pitch_phase);
  return s;
}

TableMotion::TableMotion(const std::string& path, const Vec3& centre) : ShipMotion(centre), name_(path) {
  std::ifstream in(path);
  if (!in) throw MotionError("cannot open ship motion file '" + path + "'");
  std::string line;
  std::getline(in, line);
  std::string header;
  for (char c : line)
    if (!std::isspace(static_cast<unsigned char>(c))) header += c;
  if (header != "time_s,heave_m,roll_deg,pitch_deg")
    throw MotionError("ship motion file '" + path + "': the first line must be 'time_s,heave_m,roll_deg,pitch_deg', got '" + line + "'");
  int row = 1;
  while (std::getline(in, line)) {
    ++row;
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    std::istringstream s(line);
    double v[4];
    char c[3] = {0, 0, 0};
    std::string rest;
    if (!(s >> v[0] >> c[0] >> v[1] >> c[1] >> v[2] >> c[2] >> v[3]) || c[0] != ',' || c[1] != ',' || c[2] != ',' || (s >> rest))
      throw MotionError("ship motion file '" + path + "', line " + std::to_string(row) + ": expected 4 comma-separated numbers");
    for (double x : v)
      if (!std::isfinite(x)) throw MotionError("ship motion file '" + path + "', line " + std::to_string(row) + ": a value is not finite");
    if (!t_.empty() && !(v[0] > t_.back()))
      throw MotionError("ship motion file '" + path + "', line " + std::to_string(row) + ": time must increase");
    if (std::abs(v[2]) > 45 || std::abs(v[3]) > 45)
      throw MotionError("ship motion file '" + path + "', line " + std::to_string(row) + ": roll or pitch beyond 45 deg");
    t_.push_back(v[0]);
    heave_.push_back(v[1]);
    roll_.push_back(v[2] * M_PI / 180);
    pitch_.push_back(v[3] * M_PI / 180);
  }
  if (t_.size() < 2) throw MotionError("ship motion file '" + path + "' needs at least two rows");
}

ShipPose TableMotion::pose(double t) const {
  ShipPose s;
  if (t <= t_.front() || t >= t_.back()) {
    const std::size_t k = t <= t_.front() ? 0 : t_.size() - 1;
    s.heave = heave_[k];
    s.roll = roll_[k];
    s.pitch = pitch_[k];
    return s;  // held: rates zero
  }
  const std::size_t k = static_cast<std::size_t>(std::upper_bound(t_.begin(), t_.end(), t) - t_.begin()) - 1;
  const double h = t_[k + 1] - t_[k], a = (t - t_[k]) / h;
  const auto lerp = [&](const std::vector<double>& v) { return v[k] + a * (v[k + 1] - v[k]); };
  const auto slope = [&](const std::vector<double>& v) { return (v[k + 1] - v[k]) / h; };
  s.heave = lerp(heave_);
  s.roll = lerp(roll_);
  s.pitch = lerp(pitch_);
  s.heave_rate = slope(heave_);
  s.roll_rate = slope(roll_);
  s.pitch_rate = slope(pitch_);
  return s;
}

std::unique_ptr<ShipMotion> make_motion(const std::string& which, double scale, const Vec3& centre) {
  if (!(scale > 0)) throw MotionError("ship motion: scale must be > 0");
  // Froude scaling from the 1/50 model: lengths x (scale * 50), times x sqrt(scale * 50)
  const double lambda = scale * 50.0;
  if (which == "static") return std::make_unique<StaticMotion>();
  SinusoidalMotion::Params p;
  if (which == "pitch") {  // NRC case 06: pitch 5 deg at 1 Hz on the 1/50 model (thesis 7.2)
    p.frequency = 1.0 / std::sqrt(lambda);
    p.pitch = 5.0 * M_PI / 180;
    return std::make_unique<SinusoidalMotion>("pitch", p, centre);
  }
  if (which == "heave") {  // heave 0.04 m at 1 Hz on the 1/50 model (thesis appendix II)
    p.frequency = 1.0 / std::sqrt(lambda);
    p.heave = 0.04 * lambda;
    return std::make_unique<SinusoidalMotion>("heave", p, centre);
  }
  if (which == "approach") {
    // Regular head seas Hs = 2 m (amplitude 1 m), Tp = 15 s, ship at 15 kn (NRC
    // "RegularShipMotion_Hs2_Tp15_Vs_15_HG0", whose data we do not have). Encounter frequency
    // w_e = w + w^2 U / g (head seas); a 351 m wave is long against the ship, so heave follows the
    // surface (amplitude 1 m) and pitch the wave slope k A = w^2 A / g, pitch leading heave by 90 deg
    // [EST, long-wave limit of the response amplitude operators].
    const double w = 2 * M_PI / 15.0, U = 15 * 0.514444, g = 9.80665;
    const double we = w + w * w * U / g;
    p.frequency = we / (2 * M_PI) / std::sqrt(scale);  // full-scale data: times x sqrt(scale)
    p.heave = 1.0 * scale;
    p.pitch = w * w * 1.0 / g;
    p.pitch_phase = M_PI / 2;
    return std::make_unique<SinusoidalMotion>("approach", p, centre);
  }
  if (which.size() > 4 && which.substr(which.size() - 4) == ".csv") return std::make_unique<TableMotion>(which, centre);
  throw MotionError("ship motion must be static, pitch, heave, approach or a .csv file, got '" + which + "'");
}

}  // namespace ship_lrm::wake
