// Blade dynamics in vacuo against the analytic flap and lag frequencies of a rigid blade on an offset
// hinge with spring (e.g. Padfield 2nd ed. 3.2.1; Johnson, Rotorcraft Aeromechanics, ch. 16):
//   lambda_beta^2 = 1 + e S / I + K_beta / (I Omega^2),  nu_zeta^2 = e S / I + K_zeta / (I Omega^2)
#include <gtest/gtest.h>

#include <cmath>

#include "ship_lrm/flight/helicopter.hpp"

using namespace ship_lrm::flight;
using ship_lrm::Vec3;

namespace {
// Period of the oscillation of x(t) from its upward zero crossings.
double measured_frequency(const std::function<double()>& step_and_read, double dt, int steps) {
  double prev = step_and_read(), first = -1, last = -1;
  int crossings = 0;
  for (int i = 1; i < steps; ++i) {
    const double x = step_and_read();
    if (prev < 0 && x >= 0) {
      const double t = (i - 1 + prev / (prev - x)) * dt;
      if (first < 0) first = t;
      last = t;
      ++crossings;
    }
    prev = x;
  }
  return 2 * M_PI * (crossings - 1) / (last - first);
}
}  // namespace

class BladeInVacuo : public ::testing::TestWithParam<double> {};

TEST_P(BladeInVacuo, FlapAndLagFrequenciesMatchTheory) {
  auto p = load_default_bo105();
  p.main_rotor.hinge_offset = GetParam();
  MainRotor rotor(p);
  const double om = p.main_rotor.rotor_speed;
  const double e = rotor.hinge_offset(), s = rotor.blade_first_moment(), i = rotor.blade_inertia();
  const double flap_expected = om * std::sqrt(1 + e * s / i + rotor.flap_spring() / (i * om * om));
  const double lag_expected = om * std::sqrt(e * s / i + rotor.lag_spring() / (i * om * om));
  // the configured frequencies, realised by the springs derived from them
  EXPECT_NEAR(flap_expected / om, p.main_rotor.flap_frequency_ratio, 1e-9);
  MainRotorInputs in;
  in.aerodynamics = false;
  in.rotor_speed = om;
  const double dt = 2e-4;
  rotor.blades()[0].flap = 0.01;
  const double f_flap = measured_frequency(
      [&] {
        rotor.step(in, dt, 1);
        return rotor.blades()[0].flap;
      },
      dt, 20000);
  EXPECT_NEAR(f_flap, flap_expected, 2e-3 * flap_expected);
  MainRotor rotor2(p);
  rotor2.blades()[0].lag = 0.01;
  auto q = p;
  const double damping = p.main_rotor.lag_damping_ratio;
  const double f_lag = measured_frequency(
      [&] {
        rotor2.step(in, dt, 1);
        return rotor2.blades()[0].lag;
      },
      dt, 40000);
  // damped frequency of the lag mode
  EXPECT_NEAR(f_lag, lag_expected * std::sqrt(1 - damping * damping), 5e-3 * lag_expected);
}

INSTANTIATE_TEST_SUITE_P(HingeOffsets, BladeInVacuo, ::testing::Values(0.0, 0.3, 0.6));

TEST(MainRotor, ForceHarmonicsMeanEqualsRotorForce) {
  // The harmonic record handed to the LRM (thesis 6.5) carries the rotor's mean aerodynamic force.
  const auto p = load_default_bo105();
  Helicopter heli(p, nullptr, EngineMode::ConstantSpeed);
  heli.set_body_held(true);
  BladeAngles a;
  a.main.collective = 0.12;
  a.main.forward = 0.02;
  heli.set_blade_angles(a);
  RigidBodyState s;
  s.velocity = Vec3(20, 0, 0);
  heli.reset(s);
  const int rev = static_cast<int>(std::ceil(2 * M_PI / (p.main_rotor.rotor_speed * p.time_step)));
  for (int i = 0; i < 8 * rev; ++i) heli.step();
  Vec3 mean = Vec3::Zero();
  for (int i = 0; i < rev; ++i) {
    heli.step();
    mean += heli.outputs().rotor.aero_force / rev;
  }
  const auto h = heli.main_rotor().force_record().harmonics();
  EXPECT_LT((h.cos[0] - mean).norm(), 0.01 * mean.norm()) << h.cos[0].transpose() << " vs " << mean.transpose();
  // 4 blades: the 4/rev thrust harmonic is the largest vibratory one in the fixed frame
  EXPECT_GT(mean.norm(), 1e4);
}
