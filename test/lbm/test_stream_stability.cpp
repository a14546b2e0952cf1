// The stream-stability probe (stream_stability.hpp): a viscous shear wave decays at its analytic
// rate, and plain BGK near tau = 1/2 diverges at the LRM's lattice Mach number 0.3 (Lallemand & Luo
// 2000, Phys. Rev. E 61, 6546), reported in the result rather than thrown; the recursive regularised
// collision damps what BGK grows there.
#include <gtest/gtest.h>

#include <cmath>

#include "ship_lrm/lbm/stream_stability.hpp"

using namespace ship_lrm::lbm;
using ship_lrm::ConfigError;

namespace {
// A stream through a velocity inlet and a pressure outlet at the wake's lattice viscosity (model,
// N = 48) and Smagorinsky constant, 8 000 steps.
StreamStabilityCase wake_inlet_outlet_case(int size, float mach) {
  StreamStabilityCase c;
  c.size = size;
  c.faces = StreamStabilityCase::Faces::InletOutlet;
  c.mach = mach;
  c.nu = 2.39e-5f;
  c.smagorinsky = 0.025f;
  c.steps = 8000;
  c.sample_interval = 2000;
  return c;
}

// The LRM's lattice: Mach 0.3, air's lattice viscosity at N = 32, Smagorinsky s = 0.05; 4 000 steps.
StreamStabilityCase lrm_lattice_case(int size) {
  StreamStabilityCase c;
  c.size = size;
  c.mach = 0.3f;
  c.nu = 1.37e-7f;
  c.smagorinsky = 0.05f;
  c.steps = 4000;
  c.sample_interval = 1000;
  return c;
}
}  // namespace

// u_x = U + a sin(k y) in a periodic box: the mode decays as exp(-nu k^2 t) for any U along x. At
// rest the lattice gives the rate to 0.5 % over 1000 steps (0.4 % of it in the first 200, the start at
// equilibrium without its non-equilibrium part). In a stream that start also sets off sound waves
// that modulate the mode's coefficient by up to 0.6 % more (measured 0.5 - 1.1 % in all after 1 000
// steps at Mach 0.05 - 0.3), hence 2 % there; a wrong viscous term in a stream would be off by far more.
// Both collisions (the recursive regularised one must keep BGK's viscosity).
TEST(StreamStability, ShearWaveDecaysAtTheViscousRateInAStream) {
  for (CollisionModel model : {CollisionModel::Bgk, CollisionModel::RecursiveRegularized})
    for (float mach : {0.0f, 0.15f}) {
      StreamStabilityCase c;
      c.collision = model;
      c.size = 32;
      c.mach = mach;
      c.nu = 0.01f;
      c.seed = StreamStabilityCase::Seed::ShearWave;
      c.steps = 1000;
      c.sample_interval = 500;
      const StreamStabilityResult r = run_stream_stability(c);
      ASSERT_FALSE(r.diverged);
      ASSERT_EQ(r.samples.size(), 3u);
      const double k = 2.0 * M_PI / c.size;
      const double expected = std::exp(-c.nu * k * k * c.steps);  // 0.680
      EXPECT_NEAR(r.samples.front().shear_amplitude, c.amplitude, 1e-3 * c.amplitude);
      const double tolerance = mach == 0.0f ? 0.01 : 0.02;
      EXPECT_NEAR(r.samples.back().shear_amplitude / r.samples.front().shear_amplitude, expected, tolerance * expected)
          << "Mach " << mach << ", " << to_string(model);
    }
}

// Plain BGK at the LRM's lattice viscosity (air on a 0.63 m grid) and Mach 0.3: a 1e-4 disturbance
// grows until the divergence guard trips; the probe reports the step instead of throwing.
TEST(StreamStability, PlainBgkNearHalfTauDivergesAtMach03) {
  StreamStabilityCase c;
  c.size = 16;
  c.mach = 0.3f;
  c.nu = 1.37e-7f;
  c.steps = 4000;
  const StreamStabilityResult r = run_stream_stability(c);
  EXPECT_TRUE(r.diverged);
  EXPECT_GT(r.diverged_at, 0);
  EXPECT_LT(r.diverged_at, c.steps);
  EXPECT_TRUE(std::isinf(r.growth()));
}

// The LRM's collision at its lattice Mach number 0.3 (16^3 box, air's lattice viscosity, Smagorinsky
// s = 0.05, 4 000 steps): with BGK the disturbance grows (x 16, measured) until the Smagorinsky
// viscosity holds it at a few per cent of the stream; the recursive regularised collision damps it
// (x 0.24), since it sets the ghost moments that BGK leaves undamped near tau = 1/2 to equilibrium.
// (Over 64 000 steps in a 32^3 box it regrows slowly and saturates at 0.4 % of U, BGK at 2.5 % from
// step 1 000: docs/benchmarks.md at 193c1b4, "The recursive regularised collision".)
TEST(StreamStability, RecursiveRegularisedCollisionDampsWhatBgkGrowsAtMach03) {
  StreamStabilityCase c = lrm_lattice_case(16);
  const StreamStabilityResult bgk = run_stream_stability(c);
  c.collision = CollisionModel::RecursiveRegularized;
  const StreamStabilityResult rr = run_stream_stability(c);
  ASSERT_FALSE(rr.diverged);
  EXPECT_GT(bgk.growth(), 4.0);
  EXPECT_LT(rr.growth(), 0.5);
}

// A stream through a velocity inlet and a pressure outlet (y, z periodic) at the wake's lattice viscosity
// and Smagorinsky constant, Mach 0.173 (the wake's lattice wind before 2026-12-04): with the thesis'
// reflecting inlet a 1e-4 disturbance grows (x 900 in 8 000 steps in this 16^3 box, measured; either
// collision), which is what made the wake's inlet noisy; the characteristic inlet lets it leave
// (x 0.017). The periodic box at the same Mach number decays.
TEST(StreamStability, CharacteristicInletLetsTheDisturbanceLeave) {
  StreamStabilityCase c = wake_inlet_outlet_case(16, 0.173f);
  const StreamStabilityResult reflecting = run_stream_stability(c);
  c.characteristic_inlet = true;
  const StreamStabilityResult characteristic = run_stream_stability(c);
  ASSERT_FALSE(characteristic.diverged);
  EXPECT_GT(reflecting.growth(), 10.0);
  EXPECT_LT(characteristic.growth(), 0.2);
}

// OPEN DEFECT, the goal for a fix: the LRM's velocity faces are still the thesis' reflecting inlets
// (the characteristic inlet did not remove the forward-flight ground corner's mode, 2026-12-04, so the
// LRM keeps them). In a 32^3 box at the wake's default Mach 0.078 the reflecting inlet grows a
// disturbance x 4.2 in 8 000 steps (measured). Enable when the reflecting inlet is stable.
TEST(StreamStability, DISABLED_AStreamThroughAVelocityInletAndPressureOutletStaysQuiet) {
  const StreamStabilityCase c = wake_inlet_outlet_case(32, 0.078f);
  const StreamStabilityResult r = run_stream_stability(c);
  ASSERT_FALSE(r.diverged);
  EXPECT_LT(r.growth(), 1.0);
}

// The absorbing layer (FaceCondition::absorbing_cells) in front of the reflecting inlet: the
// disturbance must decay, as it does in the periodic box. Measured with 4 cells: x 0.014 in the wake's
// case above (x 4.2 without the layer), and at the LRM's own lattice (Mach 0.3, nu 1.37e-7,
// Smagorinsky 0.05) x 0.78 in 4 000 steps where the plain inlet grows it x 800 to 79 % of the stream.
TEST(StreamStability, AnAbsorbingLayerKeepsAStreamThroughAReflectingInletQuiet) {
  StreamStabilityCase c = wake_inlet_outlet_case(32, 0.078f);
  c.absorbing_cells = 4;
  const StreamStabilityResult wake = run_stream_stability(c);
  ASSERT_FALSE(wake.diverged);
  EXPECT_LT(wake.growth(), 0.1);
  StreamStabilityCase lrm = lrm_lattice_case(32);
  lrm.faces = StreamStabilityCase::Faces::InletOutlet;
  const StreamStabilityResult plain = run_stream_stability(lrm);
  lrm.absorbing_cells = 4;
  const StreamStabilityResult absorbed = run_stream_stability(lrm);
  ASSERT_FALSE(absorbed.diverged);
  EXPECT_TRUE(plain.diverged || plain.growth() > 10.0);
  EXPECT_LT(absorbed.growth(), 1.0);
}

TEST(StreamStability, RefusesBadInput) {
  StreamStabilityCase c;
  c.mach = 0.9f;
  EXPECT_THROW(run_stream_stability(c), ConfigError);
  c.mach = 0.1f;
  c.nu = 0.0f;
  EXPECT_THROW(run_stream_stability(c), ConfigError);
  c.nu = 0.01f;
  c.amplitude = 0.5f;
  EXPECT_THROW(run_stream_stability(c), ConfigError);
}
