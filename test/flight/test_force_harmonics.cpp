// Harmonic force coefficients of thesis 6.5 recover a band-limited force distribution.
#include <gtest/gtest.h>

#include <cmath>

#include "ship_lrm/rotor/force_harmonics.hpp"

using namespace ship_lrm::rotor;
using ship_lrm::Vec3;

TEST(ForceHarmonics, RecoversKnownCoefficients) {
  // Per-blade force F_b(psi) = a0 + a1 cos psi + b2 sin 2 psi + a4 cos 4 psi + b9 sin 9 psi; four blades
  // each record their own force, so the total F(psi) = 4 F_b(psi) in every coefficient.
  const Vec3 a0(100, -20, -6000), a1(30, 0, 500), b2(0, 40, -200), a4(5, 5, 80), b9(1, 2, 3);
  const auto fb = [&](double psi) {
    return Vec3(a0 + a1 * std::cos(psi) + b2 * std::sin(2 * psi) + a4 * std::cos(4 * psi) + b9 * std::sin(9 * psi));
  };
  AzimuthForceRecord rec(4);
  // blades pass the azimuths at an arbitrary step (not a multiple of the 5 deg samples)
  const double step = 2.0 * M_PI / 78.3;
  for (int n = 0; n < 400; ++n)
    for (int b = 0; b < 4; ++b) {
      const double psi = n * step + b * M_PI / 2;
      rec.deposit(b, psi, fb(std::round(psi / (2 * M_PI / 72)) * (2 * M_PI / 72)));
    }
  const RotorForceHarmonics h = rec.harmonics();
  EXPECT_LT((h.cos[0] - 4 * a0).norm(), 1e-9);
  EXPECT_LT((h.cos[1] - 4 * a1).norm(), 1e-9);
  EXPECT_LT((h.sin[2] - 4 * b2).norm(), 1e-9);
  EXPECT_LT((h.cos[4] - 4 * a4).norm(), 1e-9);
  EXPECT_LT((h.sin[9] - 4 * b9).norm(), 1e-9);
  EXPECT_LT(h.cos[3].norm() + h.sin[1].norm() + h.cos[9].norm(), 1e-9);
  EXPECT_LT((h.at(0.3) - 4 * fb(0.3)).norm(), 1e-9);
}

TEST(ForceHarmonics, SkippedSamplesAreInterpolated) {
  // A time step of 15 deg of azimuth skips two of every three samples; they are filled by linear
  // interpolation, so a 1/rev force is still found (interpolation error <= (15 deg)^2 / 8 ~ 1 %).
  AzimuthForceRecord rec(1);
  for (int n = 0; n <= 30; ++n) rec.deposit(0, n * M_PI / 12, Vec3(std::cos(n * M_PI / 12), 0, 0));
  const auto h = rec.harmonics();
  EXPECT_NEAR(h.cos[1].x(), 1.0, 0.01);
  EXPECT_NEAR(h.cos[0].x(), 0.0, 1e-9);
  EXPECT_NEAR(h.sin[1].x(), 0.0, 1e-9);
}
