// Trim for steady straight flight: Newton iteration on the six unknowns (collective, longitudinal
// and lateral cyclic, pedal, pitch and roll attitude) that zero the six body accelerations averaged
// over a rotor revolution, with the fuselage held at the candidate attitude while the blades and
// the inflow settle to their periodic state (the rotor is integrated in time, as in flight).
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "ship_lrm/flight/helicopter.hpp"

namespace ship_lrm::flight {

struct TrimTarget {
  double speed = 0;        // m/s, flight-path speed relative to the air
  double climb_angle = 0;  // rad, flight path above the horizon
  double heading = 0;      // rad
};

struct TrimOptions {
  int max_iterations = 40;
  double tolerance = 2e-3;     // on the residual norm (see TrimResult::residual)
  int settle_revolutions = 3;  // per evaluation, before the averaging revolution
  std::optional<PilotControls> initial_controls;
  std::optional<Vec3> initial_attitude;  // (roll, pitch, yaw), rad
  // Called at each Newton iteration with its number (0: the starting point) and residual norm, before
  // the convergence test: a coupled LRM trim takes minutes per iteration at N = 64, and the
  // command-line tool shows where it is.
  std::function<void(int iteration, double residual)> progress;
};

struct TrimResult {
  bool converged = false;
  int iterations = 0;
  // Norm of (du, dv, dw)/g and (dp, dq, dr) * 1 s / 1 rad, revolution-averaged accelerations.
  double residual = 0;
  std::string message;
  PilotControls controls;
  BladeAngles angles;
  double roll = 0, pitch = 0;                              // rad
  double main_power = 0, tail_power = 0, total_power = 0;  // W, revolution averages
  double thrust = 0;                                       // N, aerodynamic, along -z_mr
  double induced_velocity = 0;                             // m/s, mean induced velocity of the inflow model
  double download = 0;                                     // N, vertical fuselage load (positive down)
  Vec3 flapping = Vec3::Zero();                            // coning, forward and right disk tilt, rad
  RigidBodyState body;                                     // trimmed fuselage state
  // d residual / d (collective, forward, right, tail [rad, blade angles], roll, pitch [rad]) near the
  // trim (the last Newton-Broyden Jacobian): how the accelerations answer the controls (ShipApproach
  // uses it to re-trim the controls for another inflow model).
  Eigen::Matrix<double, 6, 6> jacobian = Eigen::Matrix<double, 6, 6>::Zero();
};

// Trims `heli` (its parameters, inflow model and engine mode) and leaves it in the trimmed state,
// with the body released. Never throws for a trim that does not converge: check `converged`.
TrimResult trim(Helicopter& heli, const TrimTarget& target, const TrimOptions& options = {});

// Body state of straight flight at this speed, climb angle, heading and attitude.
RigidBodyState flight_state(const TrimTarget& target, double roll, double pitch);

}  // namespace ship_lrm::flight
