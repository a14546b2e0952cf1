// Ship motion (thesis 6.2, 7.2): heave, roll and pitch about a centre of motion, as
// sinusoids (the NRC wind-tunnel cases, thesis ref. [12]) or from a user's time-series file.
//
// The ship frame (ship_geometry.hpp: x forward, y starboard, z down) moves relative to the "mean
// frame", which travels with the ship's mean speed and in which the wake table is written: a body
// point p (ship frame) is at  c + R(roll, pitch) (p - c) - heave e_z  in the mean frame, with c the
// centre of motion, heave positive up, roll positive starboard down, pitch positive bow up
// (R = R_y(pitch) R_x(roll) in the FRD axes, the Euler angles with zero yaw).
#pragma once
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "ship_lrm/common/vec.hpp"
#include "ship_lrm/wake/ship_geometry.hpp"

namespace ship_lrm::wake {

class MotionError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

struct ShipPose {
  double heave = 0, roll = 0, pitch = 0;                 // m (up), rad, rad (bow up)
  double heave_rate = 0, roll_rate = 0, pitch_rate = 0;  // m/s, rad/s
};

// Where the ship is at one instant: body points (ship frame) <-> positions in the mean frame.
struct ShipPlacement {
  Mat3 rotation = Mat3::Identity();  // ship -> mean frame
  Vec3 centre = Vec3::Zero();        // centre of motion, ship frame
  double heave = 0;                  // m, up
  Vec3 to_mean(const Vec3& p) const { return centre + rotation * (p - centre) - heave * Vec3::UnitZ(); }
  Vec3 to_body(const Vec3& x) const { return centre + rotation.transpose() * (x + heave * Vec3::UnitZ() - centre); }
};

class ShipMotion {
 public:
  explicit ShipMotion(const Vec3& centre) : centre_(centre) {}
  virtual ~ShipMotion() = default;
  virtual std::string name() const = 0;
  virtual ShipPose pose(double t) const = 0;
  virtual bool is_static() const { return false; }
  const Vec3& centre() const { return centre_; }
  // Rotation ship -> mean frame and the position and velocity (mean frame) of body point p at time t.
  static Mat3 rotation(const ShipPose& s);
  ShipPlacement placement(double t) const;
  Vec3 position(const Vec3& p, double t) const;
  Vec3 velocity(const Vec3& p, double t) const;
  // Angular velocity (mean frame) and velocity of the centre of motion.
  Vec3 omega(double t) const;
  Vec3 centre_velocity(double t) const;

 protected:
  Vec3 centre_;
};

class StaticMotion final : public ShipMotion {
 public:
  StaticMotion() : ShipMotion(Vec3::Zero()) {}
  std::string name() const override { return "static"; }
  ShipPose pose(double) const override { return {}; }
  bool is_static() const override { return true; }
};

// heave(t) = A_h sin(2 pi f t + phi_h), likewise roll and pitch (amplitudes in m and rad).
class SinusoidalMotion final : public ShipMotion {
 public:
  struct Params {
    double frequency = 1.0;  // Hz
    double heave = 0, roll = 0, pitch = 0;
    double heave_phase = 0, roll_phase = 0, pitch_phase = 0;  // rad
  };
  SinusoidalMotion(std::string name, const Params& p, const Vec3& centre);
  std::string name() const override { return name_; }
  ShipPose pose(double t) const override;
  const Params& params() const { return p_; }

 private:
  std::string name_;
  Params p_;
};

// A time series from a CSV file with the header  time_s,heave_m,roll_deg,pitch_deg  and rows in
// increasing time; linear in between, rates from the segment's slope, held at the ends.
class TableMotion final : public ShipMotion {
 public:
  TableMotion(const std::string& path, const Vec3& centre);
  std::string name() const override { return name_; }
  ShipPose pose(double t) const override;
  double duration() const { return t_.back() - t_.front(); }

 private:
  std::string name_;
  std::vector<double> t_, heave_, roll_, pitch_;
};

// The named cases (thesis 7.2): "static"; "pitch": 5 deg at 1 Hz on the 1/50 model;
// "heave": 0.04 m at 1 Hz on the model; both Froude-scaled at full scale (amplitudes x 50 (heave),
// frequency / sqrt(50)); "approach": the full-scale heave + pitch of the approach (regular head
// seas, Hs 2 m, Tp 15 s, 15 kn: see docs/design.md); or a path to a CSV file (TableMotion).
// `scale` is the geometry scale (1/50 model, 1 full); `centre` the centre of motion (ship frame).
std::unique_ptr<ShipMotion> make_motion(const std::string& which, double scale, const Vec3& centre);

// The centre of motion used everywhere (the precompute and the ship walls of the LRM): mid-length on
// the waterline [EST; the NRC data set's centre is not available here].
inline Vec3 motion_centre(const ShipDatum& d) { return Vec3(d.stern_x + 0.5 * d.length, 0.0, d.waterline); }
// The landing spot (ship frame): on the centreline, on the deck (z = 0, the hangar-door base), midway
// between the stern and the hangar door (x = 0), as the ship frame's definition places them.
inline Vec3 landing_spot(const ShipDatum& d) { return Vec3(0.5 * d.stern_x, 0.0, 0.0); }

}  // namespace ship_lrm::wake
