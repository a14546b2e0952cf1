// Isolated rotor in the LRM domain (thesis 8.1, 8.2.3): a uniformly loaded disk at zero incidence in
// a stream, optionally above a ground plane, its time-averaged inflow against Pitt-Peters / momentum
// theory and the algebraic ground-effect models.
#pragma once

#include <functional>

#include "ship_lrm/lrm/domain.hpp"
#include "ship_lrm/lrm/domain_slice.hpp"

namespace ship_lrm::lrm {

struct IsolatedRotorCase {
  double speed = 0;  // m/s edgewise stream (the rotor flies forward at this speed)
  // m/s axial climb rate (>= 0): the air passes the disk downwards at this speed. Steady axial flow
  // through a uniformly loaded disk is where momentum theory is exact (Froude's theorem), the cleanest
  // check of the LRM's inflow; no ground with it (a climb over a ground plane has no steady state).
  double climb = 0;
  double thrust = 24525;      // N, uniform over the disk (thesis 8.1: Bo 105 CBS-5 MTOW)
  double settle = 4.0;        // s simulated before averaging
  double average = 2.0;       // s averaged
  double rotor_speed = 44.4;  // rad/s, only to non-dimensionalise the Pitt-Peters reference
  double ground_height = 0;   // m from the hub down to a ground plane moving at the stream; 0: none
  // the ground as a free-slip wall (WallSurface::slip) instead of a no-slip one: the inviscid wall of
  // the image models (Cheeseman & Bennett), whose tangential motion then does not matter
  bool slip_ground = false;
  bool fuselage = false;      // a Bo 105-like fuselage (walls.hpp) below the disk
  bool centre_plane = false;  // also average the x-z plane through the hub (IsolatedRotorResult::centre_plane)
  // called with the fraction of the case's LBM steps done, about every 0.05 s simulated (a progress line)
  std::function<void(double)> progress;
};

// The lattice velocity (m/s mapped to Mach 0.3, LrmConfig::reference_velocity) for forward flight in
// ground effect: twice the thesis' 30 m/s. At 30 m/s the corner where the inflow face meets the
// ground, which moves at the stream's speed, seeds a grid-scale mode that the BGK bulk, near its
// stability limit at the LRM's relaxation time, carries along the ground, and v_IGE / v_OGE jumps
// about with height (N = 32 and 64; docs/benchmarks.md at 193c1b4, "Stream stability of the collision and the
// ground corner's mode").
constexpr double kForwardGroundLatticeVelocity = 60.0;

// Algebraic ground-effect models at equal thrust, induced velocity in / out of ground effect for the
// rotor at height z over the ground (thesis figs. 8.9-8.11):
// Cheeseman & Bennett 1955 (ARC R&M 3021), with its forward-flight form (Johnson, Rotorcraft
// Aeromechanics, 2013, sec. 5.5.1): 1 - (R/4z)^2 / (1 + (V/v_i)^2), v_i the induced velocity out of
// ground effect; Hayden 1976 (J. AHS 21(3)), a power ratio: 1 / (0.9926 + 0.0379 (2R/z)^2).
double cheeseman_bennett_ratio(double z_over_R, double speed, double induced_velocity);
double hayden_ratio(double z_over_R);

struct IsolatedRotorResult {
  rotor::RotorInflow inflow;  // time average, m/s (relative to the domain)
  double induced_mean = 0;    // inflow.mean.z less the climb rate: the induced velocity through the disk
  // How steady induced_mean is: the standard deviation of the samples (one every ~0.05 s) and the
  // difference of the means over the second and the first half of the averaging window (samples are
  // correlated, so the half-window difference, not std / sqrt(n), bounds the mean's uncertainty).
  double induced_std = 0, induced_half_difference = 0;
  double pitt_peters_mean = 0, pitt_peters_cosine = 0;  // m/s, steady Pitt-Peters for the same load
  double momentum_theory = 0;                           // m/s, Glauert / climb / hover momentum theory
  long steps = 0;
  double wall_seconds = 0, simulated_seconds = 0;
  int cells_per_edge = 0;
  double ground_effective_height = 0;  // m: the bounce-back wall lies half-way between fluid and wall cells
  // With IsolatedRotorCase::centre_plane: the x-z plane through the hub (domain_slice normal 1),
  // velocity relative to the rotor averaged over the same samples as the inflow; max_mach is the
  // largest seen in any sample.
  DomainSlice centre_plane;
};

IsolatedRotorResult run_isolated_rotor(const LrmConfig& cfg, const IsolatedRotorCase& c);
// Builds the case's domain, stream and walls without stepping it: ConfigError (WallOnRotorDisk
// for a ground on the disk's cells) for every set-up run_isolated_rotor would refuse, so that a
// sweep can refuse a bad case before its first long run.
void check_isolated_rotor(const LrmConfig& cfg, const IsolatedRotorCase& c);

}  // namespace ship_lrm::lrm
