// Induced velocity of a uniformly loaded actuator disk from linear vortex theory: the wake is an
// oblique cylinder of vortex rings shed at the disk's edge and carried along the mean wake velocity
// (the air relative to the disk plus the mean induced velocity), with circulation per unit length
// gamma = 2 v, v the momentum-theory mean induced velocity (Coleman, Feingold & Stempin 1945, NACA ARR
// L5E10; Castles & De Leeuw 1954, NACA Report 1184; Heyson & Katzoff 1957, NACA Report 1319). In hover
// it gives v uniformly over the disk and 2 v far down the wake; in edgewise flight v at the centre and
// Coleman's fore-aft gradient tan(chi / 2) (chi the wake skew from the shaft). The LRM uses it as the
// rotor's own far field at its faces (LrmConfig::rotor_far_field).
#pragma once

#include <limits>

#include "ship_lrm/rotor/inflow_model.hpp"

namespace ship_lrm::rotor {

// Complete elliptic integrals of the first and second kind, K(m) and E(m), parameter m = k^2 in [0, 1)
// (std::invalid_argument otherwise), by the arithmetic-geometric mean (Abramowitz & Stegun 17.6).
void complete_elliptic_integrals(double m, double& K, double& E);

// Velocity induced at p (relative to the ring's centre) by a circular vortex ring of radius R in the
// x-y plane, circulation gamma about +z (positive: flow along +z through the ring); closed form with
// complete elliptic integrals (e.g. Yoon & Heister 2004, Int. J. Numer. Meth. Fluids 44, 665). core2: the
// squared radius of a Scully core round the filament, which keeps the field finite on the ring itself
// and leaves it exact at distances well above the core.
Vec3 vortex_ring_velocity(double radius, double gamma, const Vec3& p, double core2);

// The same ring's field far away (|p| > R): its dipole and octupole terms, within (15/8) (R / |p|)^4 of
// the dipole's field (no core).
Vec3 vortex_ring_multipole_velocity(double radius, double gamma, const Vec3& p);

class VortexCylinderWake {
 public:
  // Disk of radius R at the origin in the x-y plane of the mr frame (z down); thrust T > 0 along -z
  // (the induced flow goes along +z); air: the air's velocity relative to the disk (m/s). The wake is
  // cut at `length` (in radii) and discretised in rings `spacing` radii apart; core: the core radius
  // in m (at least the spacing). Throws std::invalid_argument for bad input, or when momentum theory
  // finds no induced velocity or a wake that stays at the disk (the vortex-ring state of a descent).
  VortexCylinderWake(double radius, double thrust, double density, const Vec3& air, double core, double spacing = 0.1,
                     double length = 40.0);

  // A ground plane parallel to the disk, `height` m below it (the plane z = height of the disk frame):
  // the rings that would lie in or beyond it are cut, and every ring left gets its mirror image in the
  // plane with the opposite circulation, so that no flow crosses the plane (the image system of
  // Knight & Hegner 1941, NACA TN 835). Outside the wake the air then leaves radially along the ground
  // instead of passing through it. infinity (the default): no ground. Throws std::invalid_argument for
  // a height that is not > 0.
  void set_ground(double height);
  double ground() const { return ground_; }

  double mean_induced() const { return v_; }         // v, m/s along +z
  const Vec3& wake_direction() const { return d_; }  // unit vector of the wake's axis
  Vec3 velocity(const Vec3& p) const;                // induced velocity at p (mr frame, from the hub), m/s

 private:
  double radius_, v_, ds_, core2_;
  double ground_ = std::numeric_limits<double>::infinity();
  int rings_;
  Vec3 d_;
};

}  // namespace ship_lrm::rotor
