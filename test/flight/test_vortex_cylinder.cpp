// The vortex-cylinder wake of a uniformly loaded disk (rotor/vortex_cylinder.hpp) against the closed
// forms of vortex theory: a ring's field on its axis (Lamb, Hydrodynamics), the semi-infinite
// cylinder's uniform v on the disk and 2 v far down the wake (momentum theory's hover), and in
// edgewise flight Coleman, Feingold & Stempin's (1945) centre value v and fore-aft gradient
// dv/dx = tan(chi / 2) v / R at the centre.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "ship_lrm/rotor/momentum_theory.hpp"
#include "ship_lrm/rotor/vortex_cylinder.hpp"

using namespace ship_lrm::rotor;

namespace {
constexpr double kR = 4.92, kT = 24525, kRho = 1.1934;
}

TEST(VortexRing, OnItsAxisTheFieldIsLambsClosedForm) {
  const double R = 2.0, G = 3.0;
  for (double z : {-3.0, -0.5, 0.0, 0.7, 4.0}) {
    const Vec3 u = vortex_ring_velocity(R, G, Vec3(0, 0, z), 0.0);
    EXPECT_NEAR(u.z(), G * R * R / (2.0 * std::pow(R * R + z * z, 1.5)), 1e-12) << z;
    EXPECT_NEAR(u.x(), 0.0, 1e-12);
  }
  // in the ring's plane the flow is axial only; off the axis it is finite, and it turns round the ring
  const Vec3 in_plane = vortex_ring_velocity(R, G, Vec3(1.0, 0.5, 0.0), 0.0);
  EXPECT_NEAR(in_plane.x(), 0.0, 1e-12);
  EXPECT_GT(in_plane.z(), 0.0);
  EXPECT_LT(vortex_ring_velocity(R, G, Vec3(3.0, 0.0, 0.0), 0.0).z(), 0.0);  // outside: back-flow
}

TEST(VortexCylinder, InHoverTheDiskSeesMomentumTheoryAndTheFarWakeTwice) {
  const VortexCylinderWake w(kR, kT, kRho, Vec3::Zero(), 0.0, 0.02, 400.0);
  const double vh = hover_induced_velocity(kT, kRho, kR);
  EXPECT_NEAR(w.mean_induced(), vh, 1e-9 * vh);
  for (double r : {0.0, 0.5, 0.8}) EXPECT_NEAR(w.velocity(Vec3(r * kR, 0, 0)).z(), vh, 0.005 * vh) << r;
  EXPECT_NEAR(w.velocity(Vec3(0, 0, 100 * kR)).z(), 2.0 * vh, 0.005 * vh);
  EXPECT_NEAR(w.velocity(Vec3(0, 0, -100 * kR)).z(), 0.0, 1e-3 * vh);  // far above: still air
}

TEST(VortexCylinder, EdgewiseTheCentreHasGlauertsVelocityAndColemansGradient) {
  for (double V : {10.0, 30.0, 65.0}) {
    const VortexCylinderWake w(kR, kT, kRho, Vec3(-V, 0, 0), 0.0, 0.01, 400.0);
    const double v = glauert_induced_velocity(kT, kRho, kR, V);
    EXPECT_NEAR(w.mean_induced(), v, 1e-9 * v);
    EXPECT_NEAR(w.velocity(Vec3::Zero()).z(), v, 0.01 * v) << V;
    const double chi = std::atan2(V, v), h = 0.05 * kR;
    // the wake trails aft (-x): the inflow grows towards the rear of the disk
    const double gradient = (w.velocity(Vec3(-h, 0, 0)).z() - w.velocity(Vec3(h, 0, 0)).z()) / (2 * h);
    EXPECT_NEAR(gradient, std::tan(chi / 2) * v / kR, 0.05 * std::tan(chi / 2) * v / kR) << V;
  }
}

TEST(VortexCylinder, BadInputIsRefused) {
  EXPECT_THROW(VortexCylinderWake(0.0, kT, kRho, Vec3::Zero(), 0.0), std::invalid_argument);
  EXPECT_THROW(VortexCylinderWake(kR, -1.0, kRho, Vec3::Zero(), 0.0), std::invalid_argument);
  EXPECT_THROW(VortexCylinderWake(kR, kT, kRho, Vec3(NAN, 0, 0), 0.0), std::invalid_argument);
  EXPECT_THROW(VortexCylinderWake(kR, kT, kRho, Vec3::Zero(), 0.0, 0.0), std::invalid_argument);  // no ring spacing
}
