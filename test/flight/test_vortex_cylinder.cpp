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

// Over a ground plane h below the disk the wake is cut at the ground and mirrored in it with the
// opposite circulation (Knight & Hegner 1941). On the axis a cylinder of rings between distances z1
// and z2 from the point induces (gamma / 2) (z2 / sqrt(z2^2 + R^2) - z1 / sqrt(z1^2 + R^2)), so with
// gamma = 2 v the disk's centre sees v (2h / sqrt(h^2 + R^2) - 2h / sqrt(4h^2 + R^2)): 0.520 v at
// h = R. No flow crosses the ground, in hover and with the wake skewed.
TEST(VortexCylinder, OverGroundTheImageCylinderGivesTheClosedFormOnTheAxisAndNoFlowThroughTheGround) {
  const double vh = hover_induced_velocity(kT, kRho, kR);
  for (double h_over_R : {0.5, 1.0, 2.0}) {
    VortexCylinderWake w(kR, kT, kRho, Vec3::Zero(), 0.0, 0.01, 400.0);
    const double h = h_over_R * kR;
    w.set_ground(h);
    const double expected = vh * (2 * h / std::hypot(h, kR) - 2 * h / std::hypot(2 * h, kR));
    EXPECT_NEAR(w.velocity(Vec3::Zero()).z(), expected, 1e-3 * vh) << h_over_R;
    for (double x : {0.0, 0.5, 1.5, 3.0})  // inside the wake and outside it
      EXPECT_NEAR(w.velocity(Vec3(x * kR, 0.3 * kR, h)).z(), 0.0, 1e-9 * vh) << h_over_R << " " << x;
    // outside the wake the air leaves along the ground
    EXPECT_GT(w.velocity(Vec3(1.5 * kR, 0, 0.95 * h)).x(), 0.0) << h_over_R;
  }
  VortexCylinderWake skewed(kR, kT, kRho, Vec3(-12.0, 0, 0), 0.0, 0.02, 400.0);
  skewed.set_ground(kR);
  for (double x : {-4.0, -1.0, 0.0, 1.0, 3.0}) EXPECT_NEAR(skewed.velocity(Vec3(x * kR, 0.2 * kR, kR)).z(), 0.0, 1e-9 * vh) << x;
  EXPECT_THROW(skewed.set_ground(0.0), std::invalid_argument);
  EXPECT_THROW(skewed.set_ground(std::nan("")), std::invalid_argument);
}

TEST(VortexCylinder, BadInputIsRefused) {
  EXPECT_THROW(VortexCylinderWake(0.0, kT, kRho, Vec3::Zero(), 0.0), std::invalid_argument);
  EXPECT_THROW(VortexCylinderWake(kR, -1.0, kRho, Vec3::Zero(), 0.0), std::invalid_argument);
  EXPECT_THROW(VortexCylinderWake(kR, kT, kRho, Vec3(NAN, 0, 0), 0.0), std::invalid_argument);
  EXPECT_THROW(VortexCylinderWake(kR, kT, kRho, Vec3::Zero(), 0.0, 0.0), std::invalid_argument);  // no ring spacing
}
