// Linear stability of a uniform stream on the lattice: a periodic box holding the stream U along x
// plus a small perturbation, stepped to see whether the perturbation decays or grows.
//
// BGK at a relaxation time near 1/2 (the LRM's: air's viscosity on a metre-scale grid gives a lattice
// viscosity of order 1e-7) is linearly unstable above a lattice Mach number of a few tenths (Lallemand &
// Luo 2000, Phys. Rev. E 61, 6546, section V; Siebert, Hegele & Philippi 2008, Phys. Rev. E 77, 026707).
// An unstable stream turns any disturbance (a corner of the domain, a wall entering it) into grid-scale
// noise that grows until the Smagorinsky viscosity it stirs up holds it, or diverges without it. This
// probe measures that for the collision the solvers use, at the Mach numbers the LRM runs at.
#pragma once

#include <string>
#include <vector>

#include "ship_lrm/lbm/solver.hpp"

namespace ship_lrm::lbm {

struct StreamStabilityCase {
  int size = 32;             // cells per edge of the periodic box
  float mach = 0.3f;         // stream speed U / c_s along x
  float nu = 1e-7f;          // lattice viscosity
  float smagorinsky = 0.0f;  // Smagorinsky constant s (0: none)
  CollisionModel collision = CollisionModel::Bgk;
  // Periodic: a periodic box (the collision alone). InletOutlet: x has a velocity inlet (U at -x) and a
  // pressure outlet (+x), y and z stay periodic: the open faces with the stream through them.
  enum class Faces { Periodic, InletOutlet } faces = Faces::Periodic;
  bool characteristic_inlet = false;  // InletOutlet: FaceCondition::characteristic_inlet
  int absorbing_cells = 0;            // InletOutlet: FaceCondition::absorbing_cells (strength 0.5)
  float amplitude = 1e-4f;            // perturbation, lattice velocity units
  enum class Seed { Random, ShearWave } seed = Seed::Random;
  unsigned random_seed = 1;  // Random: every velocity component uniform in +- amplitude
  long steps = 2000;
  long sample_interval = 250;
  Backend backend = Backend::Cpu;
};

struct StreamStabilitySample {
  long step = 0;
  double max_deviation = 0;    // max over cells of |u - U| (lattice units)
  double shear_amplitude = 0;  // ShearWave: the amplitude of the seeded mode (its Fourier coefficient)
};

struct StreamStabilityResult {
  std::vector<StreamStabilitySample> samples;
  bool diverged = false;
  long diverged_at = -1;  // step at which the divergence guard tripped
  // max_deviation at the end over that at the start (the first sample); infinite if diverged
  double growth() const;
};

// Runs the case; a divergence is reported in the result, not thrown. ShearWave seeds
// u_x = U + amplitude sin(2 pi y / size), a viscous mode that decays as exp(-nu k^2 t) (k = 2 pi / size)
// whatever the stream along x (Galilean invariance), which checks the probe (shear_amplitude).
StreamStabilityResult run_stream_stability(const StreamStabilityCase& c);

}  // namespace ship_lrm::lbm
