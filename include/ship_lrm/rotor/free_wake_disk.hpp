// A uniformly loaded actuator disk with a free (force-free, self-convecting) vortex-ring wake: an
// independent, nonlinear reference for the disk's mean induced velocity, by a Lagrangian method that
// shares nothing with the lattice-Boltzmann LRM and assumes nothing about the wake's shape.
//
// The method (the actuator disk's vortex-ring model, e.g. Oye 1990, "A simple vortex model of a
// turbine rotor", 3rd IEA Symposium on the Aerodynamics of Wind Turbines; Bontempo & Manna 2019,
// Int. J. Turbomach. Propuls. Power 4, 8, for the axial case): a disk with a uniform pressure jump
// dp = T / A is a dipole sheet whose strength grows at dp / rho, i.e. an edge vortex whose circulation
// grows at dGamma/dt = dp / rho = 2 v_h^2 (unsteady Bernoulli across the disk). Every time step dt a ring
// of circulation 2 v_h^2 dt leaves the edge; every ring's nodes move with the air relative to the disk
// plus the velocity all rings induce there (Biot-Savart on straight segments with van Garrel's
// regularisation, 2003, ECN-C--03-079; second-order Runge-Kutta). The mean induced velocity is the flux through
// the disk, taken as the circulation of the wake's vector potential round the edge (Stokes; for a
// straight segment A has a closed form), so no ring ever has to be evaluated on the disk itself.
//
// What it answers: the mean induced velocity of the same actuator disk the LRM resolves (uniform
// thrust, no blades, no viscosity) in level flight and climbs, in particular in the transition regime
// (edgewise speed comparable with v_h) where Glauert's formula is a hypothesis, not a result. There
// the wake rolls up and the answer still falls with each refinement of step and core at the
// resolutions reached on a 2-core CPU (docs/benchmarks.md at 193c1b4, 2026-12-05): read it with its resolution.
// Exact references it meets (test/flight/test_free_wake_disk.cpp): in axial flow the mean induced
// velocity of a uniformly loaded disk is momentum theory's (Froude: the disk's mean velocity is the
// mean of the far upstream and far wake velocities, exact for uniform loading); in fast edgewise flight
// the disk is a wing with elliptic span loading and its mean downwash is T / (2 rho A V) (Prandtl's
// lifting-line theory), Glauert's limit.
#pragma once

#include <functional>
#include <vector>

#include "ship_lrm/rotor/inflow_model.hpp"

namespace ship_lrm::rotor {

struct FreeWakeDiskConfig {
  double radius = 4.92;     // m (the LRM's, lrm::LrmConfig)
  double thrust = 24525.0;  // N, along -z of the mr frame (z down): the induced flow goes along +z
  double density = 1.1934;  // kg/m^3
  Vec3 air = Vec3::Zero();  // the air's velocity relative to the disk far upstream, mr frame, m/s
                            // (edgewise flight at V: (-V, 0, 0); a climb at V_c: (0, 0, V_c))
  // Numerics, nondimensional with R and v_h (time unit R / v_h):
  int ring_points = 48;    // nodes per ring (straight segments between them)
  double step = 0.025;     // time step: one ring per step
  double core = 0.025;     // eps / R in the segments' regularisation r1 r2 (r1 r2 + r1.r2) + eps^2 |L|^2:
                           // a segment's velocity peaks sqrt(2) eps from it (the convection only)
  double wake_age = 6.0;   // rings older than this are dropped
  double merge_age = 1.5;  // two neighbouring rings of the same level merge when both are older than
                           // merge_age 2^level (the far wake in fewer, stronger rings); <= 0: never
  double settle = 3.0;     // time before the averaging starts (after the wake_age has filled)
  double average = 2.0;    // averaging window
  int edge_points = 256;   // quadrature points of the flux integral round the edge
  // called at every sample of the mean (every ~0.05 R / v_h) with the fraction of the run's work done
  // (each step's O(rings^2) sum counted as such, so that the fraction tracks the wall clock while the
  // wake fills) and the latest mean induced velocity in m/s (a progress line)
  std::function<void(double fraction, double mean)> progress;
};

struct FreeWakeDiskSample {
  double time;  // s
  double mean;  // mean induced velocity over the disk, m/s along +z
};

struct FreeWakeDiskResult {
  double mean = 0.0;            // time-averaged mean induced velocity, m/s (+z)
  double min = 0.0, max = 0.0;  // its range over the averaging window
  double momentum = 0.0;        // momentum theory's (Glauert's) value for the same state, m/s
  double hover = 0.0;           // v_h, m/s
  int rings = 0;                // the wake at the end
  long steps = 0;
  std::vector<FreeWakeDiskSample> history;  // every sample taken
};

// Sets step, wake_age and merge_age from lengths along the wake (in R): rings `spacing` apart, the wake
// cut `length` behind the disk and merged from `merge_length` on, with the wake's speed taken as
// momentum theory's |air + v| (so that the resolution means the same at every speed). Throws
// std::invalid_argument for lengths that are not > 0 or a descent (see solve_free_wake_disk).
void set_wake_lengths(FreeWakeDiskConfig& config, double spacing, double length, double merge_length);

// Runs the wake from the impulsive start to settle + average after the wake has reached its full
// age (simulated time wake_age + settle + average, in R / v_h). Throws std::invalid_argument for bad input (non-positive dimensions or
// thrust, fewer than 8 ring points, a step, core or wake age out of range, or a descent: air passing the disk against the induced flow, air
// z < 0, where the vortex-ring and windmill states have no steady wake to converge).
FreeWakeDiskResult solve_free_wake_disk(const FreeWakeDiskConfig& config);

}  // namespace ship_lrm::rotor
