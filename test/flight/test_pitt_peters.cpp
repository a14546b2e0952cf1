// Pitt-Peters inflow against momentum theory (hover), Glauert (edgewise flight), the Pitt-Peters
// wake-skew gradient and the apparent-mass time constant.
#include <gtest/gtest.h>

#include <cmath>

#include "ship_lrm/rotor/momentum_theory.hpp"
#include "ship_lrm/rotor/pitt_peters.hpp"

using namespace ship_lrm::rotor;
using ship_lrm::Vec3;

namespace {
// The thesis' inflow test case (thesis table 6.4): T = 24525 N, R = 4.92 m, rho = 1.1934 kg/m^3.
RotorDiskState disk(double thrust, double speed) {
  RotorDiskState s;
  s.radius = 4.92;
  s.rotor_speed = 44.4;
  s.density = 1.1934;
  s.hub_velocity = Vec3(speed, 0, 0);
  s.aero_force = Vec3(0, 0, -thrust);
  return s;
}
}  // namespace

TEST(PittPeters, HoverEqualsMomentumTheory) {
  PittPetersInflow pp;
  pp.reset(disk(24525, 0));
  const double v = pp.inflow().mean.z();
  EXPECT_NEAR(v, hover_induced_velocity(24525, 1.1934, 4.92), 1e-6);
  EXPECT_NEAR(v, 11.62, 0.005);  // the thesis' 11.62 m/s
  EXPECT_NEAR(pp.inflow().sine.z(), 0, 1e-12);
  EXPECT_NEAR(pp.inflow().cosine.z(), 0, 1e-12);
}

TEST(PittPeters, EdgewiseFlightEqualsGlauertAndSkewGradient) {
  for (double speed : {5.0, 15.0, 30.0, 65.0}) {
    PittPetersInflow pp;
    const RotorDiskState s = disk(24525, speed);
    pp.reset(s);
    const auto lam = pp.states();
    const double tip = s.rotor_speed * s.radius;
    EXPECT_NEAR(lam[0] * tip, glauert_induced_velocity(24525, 1.1934, 4.92, speed), 1e-6) << speed;
    // Pitt-Peters' static longitudinal gradient: lambda_c = 15 pi / 32 tan(chi / 2) lambda_0
    const double chi = std::atan2(speed / tip, lam[0]);
    EXPECT_NEAR(lam[2], 15.0 * M_PI / 32.0 * std::tan(0.5 * chi) * lam[0], 1e-9) << speed;
    EXPECT_GT(lam[2], 0) << "more inflow at the rear of the disk";
  }
}

TEST(PittPeters, HoverTimeConstantIsApparentMassOverMassFlow) {
  // Linearised hover: (8/3pi) dlambda/dtau = dC_T - 4 lambda_0 dlambda  =>  tau = (8/3pi) / (4 lambda_0 Omega)
  PittPetersInflow pp;
  RotorDiskState s = disk(24525, 0);
  pp.reset(s);
  const double l0 = pp.states()[0];
  s.aero_force.z() *= 1.002;  // a small step keeps it linear
  PittPetersInflow target;
  target.reset(s);
  const double l1 = target.states()[0];
  const double tau = 8.0 / (3.0 * M_PI) / (4.0 * l0 * s.rotor_speed);
  const double dt = 1e-4;
  double t = 0;
  while ((pp.states()[0] - l0) < (1 - std::exp(-1.0)) * (l1 - l0)) {
    pp.advance(s, dt);
    t += dt;
  }
  EXPECT_NEAR(t, tau, 0.01 * tau);
}
