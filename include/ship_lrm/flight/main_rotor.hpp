// Main rotor: rigid blades on a coincident flap-lag hinge at offset e with springs (the equivalent
// hinge model of a hingeless rotor, Padfield 2nd ed. 3.2.1), blade elements between the radial
// stations with table polars (thesis 6.6), and the hub loads they pass to the fuselage.
//
// Blade kinematics (rotor computation frame c: x forward, y starboard, z down along the shaft, the
// blades turning counterclockwise seen from above; a clockwise rotor is computed in the mirror image
// y -> -y of the mr frame): the hinge sits at e e_r(psi), the blade points along
//   b = cos(beta) e_r(phi) - sin(beta) z,  phi = psi - zeta,  e_r(a) = (-cos a, sin a, 0), e_t = de_r/da,
// so an element at distance s from the hinge is at p = e e_r(psi) + s b. The flap and lag equations are
// Lagrange's equations of this rigid blade with the hub moving (rates omega, acceleration a_hub),
// evaluated exactly with the blade's mass moments m, S, I about the hinge (uniform blade):
//   I beta''              = Q_beta - K_beta beta - (S n.A + I n.B)
//   I cos^2(beta) zeta''  = Q_zeta - K_zeta zeta - C_zeta zeta' + cos(beta) (S t.A + I t.B)
// with n = db/dbeta, t = e_t(phi), Q the generalised aerodynamic forces and a0(s) = A + s B the
// absolute acceleration of the blade point at s when beta'' = zeta'' = 0. In vacuo this gives the
// flap frequency lambda_beta^2 = 1 + e S / I + K_beta / (I Omega^2) (checked by a test).
// The springs follow from the configured flap and lag frequency ratios.
//
// Rotor-fuselage coupling: the blade accelerations depend on the hub's acceleration and the hub loads
// on the blade accelerations (an algebraic loop; the blades carry about a third of the roll inertia).
// Both are affine in x = (hub specific force, body angular acceleration), so each sub-step hands
// W(x) = W0 + K x to a coupling function that solves the fuselage's equations together with it and
// returns x; a one-step-delayed x instead would make the lag/roll coupling numerically unstable at
// the 1.8 ms coupling step.
#pragma once

#include <functional>
#include <vector>

#include "ship_lrm/flight/parameters.hpp"
#include "ship_lrm/flight/rigid_body.hpp"
#include "ship_lrm/rotor/force_harmonics.hpp"
#include "ship_lrm/rotor/inflow_model.hpp"

namespace ship_lrm::flight {

struct BladeState {
  double flap = 0, flap_rate = 0;  // rad, rad/s (up positive)
  double lag = 0, lag_rate = 0;    // rad, rad/s (lagging behind the rotation positive)
};

// Blade pitch in the rotor frame: theta = collective + twist (r/R - r_ref) - forward sin(psi_c) - right cos(psi_c)
// (maximum pitch where it tilts the disk the requested way after the ~90 deg flap phase lag).
struct BladePitch {
  double collective = 0;  // rad at the twist reference radius
  double forward = 0;     // rad, longitudinal cyclic amplitude tilting the disk forward
  double right = 0;       // rad, lateral cyclic amplitude tilting the disk to starboard
};

// Everything the rotor needs from outside for one step; vectors in mr axes.
struct MainRotorInputs {
  BladePitch pitch;
  rotor::RotorInflow inflow;      // air velocity relative to the mr frame over the disk
  Vec3 body_rate = Vec3::Zero();  // rad/s
  Vec3 body_angular_acceleration = Vec3::Zero();
  Vec3 hub_specific_force = Vec3::Zero();          // hub acceleration minus gravity, m/s^2 (-g in hover)
  double rotor_speed = 0, rotor_acceleration = 0;  // rad/s, rad/s^2
  double density = 1.225, speed_of_sound = 340.3;
  bool aerodynamics = true;
};

// Loads on the hub, mr axes, averaged over the step.
struct MainRotorLoads {
  Vec3 force = Vec3::Zero(), moment = Vec3::Zero();            // aerodynamic + blade inertial (relative motion), about the hub
  Vec3 aero_force = Vec3::Zero(), aero_moment = Vec3::Zero();  // aerodynamic only
  double aero_torque = 0;                                      // N m resisting the rotation (shaft torque needed)
  double blade_pitch_moment = 0;                               // N m, sum of the section moments about the pitch axes of all blades
};

using Vec6 = Eigen::Matrix<double, 6, 1>;
using Mat6 = Eigen::Matrix<double, 6, 6>;
// Given the hub wrench W(x) = w0 + k x (force and moment about the hub, mr axes) returns x = (hub
// specific force, body angular acceleration) in mr axes.
using RotorCoupling = std::function<Vec6(const Vec6& w0, const Mat6& k)>;

class MainRotor {
 public:
  explicit MainRotor(const HelicopterParameters& params);

  // Integrate the blades over dt in `substeps` semi-implicit Euler steps; the azimuth advances with
  // the rotor speed. Returns the step-averaged hub loads and records the blade forces over azimuth.
  // With `coupling`, x is solved with the fuselage every sub-step (in.hub_specific_force and
  // in.body_angular_acceleration are then ignored); without it they are taken as given.
  MainRotorLoads step(const MainRotorInputs& in, double dt, int substeps, const RotorCoupling* coupling = nullptr);
  // Loads and blade accelerations for the current state without advancing it.
  MainRotorLoads evaluate(const MainRotorInputs& in) const;

  std::vector<BladeState>& blades() { return blades_; }
  const std::vector<BladeState>& blades() const { return blades_; }
  double azimuth() const { return azimuth_; }  // rad, blade 0, in the rotor's own sense of rotation
  void set_azimuth(double a) { azimuth_ = a; }
  // Geometric azimuth of blade i (inflow_model.hpp convention).
  double geometric_azimuth(int blade) const;
  // Multiblade flapping (rad): coning, and the disk tilt forward and to starboard (mr frame).
  Vec3 multiblade_flap() const;
  const rotor::AzimuthForceRecord& force_record() const { return record_; }
  rotor::AzimuthForceRecord& force_record() { return record_; }

  double radius() const { return radius_; }
  double flap_spring() const { return k_flap_; }
  double lag_spring() const { return k_lag_; }
  // Blade mass moments about the hinge.
  double blade_mass() const { return mass_; }
  double blade_first_moment() const { return first_moment_; }
  double blade_inertia() const { return inertia_; }
  double hinge_offset() const { return hinge_; }
  bool clockwise() const { return clockwise_; }

 private:
  struct Element {
    double s, r_over_R, dr;
    double lift_fraction;  // part of the element inboard of the tip-loss radius B R
  };
  struct BladeResult {
    double flap_acc, lag_acc;
    Vec3 force, moment, aero_force, aero_moment;  // computation frame
    double pitch_moment;
    Vec6 flap_gain, lag_gain;   // d(flap_acc)/dx, d(lag_acc)/dx, x in the computation frame
    Vec3 nhat, that_cb, lever;  // for the loads' dependence on the blade accelerations
  };
  BladeResult blade(const MainRotorInputs& in, const Vec3& w, const Vec3& wdot, const Vec3& ahub, double psi, const BladeState& b,
                    double theta0, double fwd, double right) const;

  // Sums over the blades (computation frame) times `scale`, as loads in mr axes.
  MainRotorLoads to_mr(const Vec3& f, const Vec3& m, const Vec3& fa, const Vec3& ma, double pitch_moment, double scale) const;

  bool clockwise_;
  int nblades_;
  double radius_, chord_, twist_, twist_ref_, hinge_;
  double mass_, first_moment_, inertia_, k_flap_, k_lag_, c_lag_;
  std::vector<Element> elements_;
  const AirfoilTable* polar_;
  AirfoilTable polar_storage_;
  std::vector<BladeState> blades_;
  double azimuth_ = 0;
  rotor::AzimuthForceRecord record_;
  std::vector<BladeResult> scratch_;
};

}  // namespace ship_lrm::flight
