// The rotor <-> inflow interface of thesis section 6.5, shared by the Pitt-Peters model (here) and the
// LRM fluid domain (module lrm): the flight model hands over the rotor's state and aerodynamic loads,
// the inflow model returns the air velocity over the disk as a mean plus first harmonics linear in r.
//
// Frames and signs (used everywhere in this interface):
//  * mr: the main-rotor frame, origin at the hub, fixed to the fuselage, not rotating with the blades;
//    x forward, y starboard, z down along the shaft (thesis fig. 5.4).
//  * psi: geometric azimuth of a point on the disk, measured from the aft direction (-x_mr) towards
//    starboard (+y_mr); a point at radius r sits at r (-cos psi, sin psi, 0). This holds for either
//    sense of rotor rotation.
//  * Forces are the aerodynamic forces ON the rotor blades (thrust is -z); moments about the hub.
#pragma once

#include <array>
#include <string>

#include "ship_lrm/common/vec.hpp"

namespace ship_lrm::rotor {

constexpr int kHarmonicOrder = 9;    // N_harm of thesis 6.5 (k = 0..9)
constexpr int kAzimuthSamples = 72;  // N_psi of thesis 6.5

// v(r, psi) = mean + sine (r/R) sin psi + cosine (r/R) cos psi: the air velocity relative to the mr
// frame (which moves and rotates with the fuselage), in mr axes, m/s.
struct RotorInflow {
  Vec3 mean = Vec3::Zero(), sine = Vec3::Zero(), cosine = Vec3::Zero();
  Vec3 at(double r_over_R, double psi) const;
};

// F(psi) = sum_k cos_k cos(k psi) + sin_k sin(k psi) (thesis 6.5); cos[0] is the mean (total) force.
struct RotorForceHarmonics {
  std::array<Vec3, kHarmonicOrder + 1> cos{}, sin{};
  RotorForceHarmonics() {
    for (auto& v : cos) v.setZero();
    for (auto& v : sin) v.setZero();
  }
  Vec3 at(double psi) const;
};

// What an inflow model gets from the flight model every coupling step.
struct RotorDiskState {
  double time = 0;                   // s
  double radius = 0;                 // m
  double rotor_speed = 0;            // rad/s (magnitude)
  double density = 0;                // kg/m^3
  Vec3 hub_velocity = Vec3::Zero();  // hub velocity relative to the undisturbed air, mr axes, m/s
  Vec3 body_rate = Vec3::Zero();     // angular velocity of the mr frame, mr axes, rad/s
  Vec3 aero_force = Vec3::Zero();    // total aerodynamic force on the blades, mr axes, N
  Vec3 aero_moment = Vec3::Zero();   // its moment about the hub, mr axes, N m
  RotorForceHarmonics harmonics;     // aerodynamic force over azimuth, thesis 6.5
  // Where the rotor is in the flight model's world frame (NED), for inflow models that place a
  // domain there (the LRM around a freely flying helicopter).
  Vec3 hub_position = Vec3::Zero();                           // m
  Eigen::Matrix3d mr_to_world = Eigen::Matrix3d::Identity();  // rotation mr axes -> world axes
  Vec3 hub_world_velocity = Vec3::Zero();                     // m/s, world axes, relative to the world (not the air)
};

// Adds the apparent air motion -omega x p of a frame rotating at `body_rate` (mr axes) over the disk,
// p = r (-cos psi, sin psi, 0): exactly linear in (r/R) cos psi and (r/R) sin psi.
void add_frame_rotation(RotorInflow& in, const Vec3& body_rate, double radius);

class InflowModel {
 public:
  virtual ~InflowModel() = default;
  virtual std::string name() const = 0;
  // Start from the steady state that belongs to this rotor state.
  virtual void reset(const RotorDiskState& state) = 0;
  // Advance the model's own states over dt with the loads of `state`.
  virtual void advance(const RotorDiskState& state, double dt) = 0;
  virtual RotorInflow inflow() const = 0;
  // Whether advance() reads state.harmonics (computing them costs time, so only then are they filled).
  virtual bool needs_harmonics() const { return false; }
};

}  // namespace ship_lrm::rotor
