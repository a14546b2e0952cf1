// The vortex-cylinder wake of a uniformly loaded disk (rotor/vortex_cylinder.hpp) against the closed
// forms of vortex theory: a ring's field on its axis (Lamb, Hydrodynamics), the semi-infinite
// cylinder's uniform v on the disk and 2 v far down the wake (momentum theory's hover), and in
// edgewise flight Coleman, Feingold & Stempin's (1945) centre value v and fore-aft gradient
// dv/dx = tan(chi / 2) v / R at the centre.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "ship_lrm/rotor/momentum_theory.hpp"
#include "ship_lrm/rotor/vortex_cylinder.hpp"

using namespace ship_lrm::rotor;
using ship_lrm::Vec3;

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

TEST(EllipticIntegrals, TheArithmeticGeometricMeanGivesTheStandardLibrarysValues) {
  for (double m : {0.0, 1e-6, 0.1, 0.5, 0.9, 0.999, 0.999999}) {
    double K, E;
    complete_elliptic_integrals(m, K, E);
    const double k = std::sqrt(m);
    EXPECT_NEAR(K, std::comp_ellint_1(k), 1e-10 * std::comp_ellint_1(k)) << m;  // k = sqrt(m) costs digits near 1
    EXPECT_NEAR(E, std::comp_ellint_2(k), 1e-12) << m;
  }
  double K, E;
  complete_elliptic_integrals(0.0, K, E);
  EXPECT_NEAR(K, M_PI / 2, 1e-15);
  EXPECT_THROW(complete_elliptic_integrals(1.0, K, E), std::invalid_argument);
  EXPECT_THROW(complete_elliptic_integrals(-0.1, K, E), std::invalid_argument);
  EXPECT_THROW(complete_elliptic_integrals(std::nan(""), K, E), std::invalid_argument);
}

// The core round the filament: at the core radius c the ring is locally a line vortex with Scully's
// core, gamma / (4 pi c); off the filament the field is the exact one, also right next to the axis,
// where the radial component vanishes (a core added to the distances instead made it grow as 1 / rho
// there: 169 m/s at an LRM face cell, 2026-12-03).
TEST(VortexRing, TheCoreSmoothsOnlyTheFilament) {
  const double R = 2.0, G = 3.0, c = 1e-3 * R;
  const Vec3 at_core = vortex_ring_velocity(R, G, Vec3(R - c, 0, 0), c * c);
  EXPECT_NEAR(at_core.norm(), G / (4 * M_PI * c), 0.01 * G / (4 * M_PI * c));
  EXPECT_EQ(vortex_ring_velocity(R, G, Vec3(R, 0, 0), c * c).norm(), 0.0);
  for (double rho : {1e-9, 1e-6, 1e-3, 0.3}) {
    const Vec3 p(rho * R, 0, 2.0 * R);
    const Vec3 cored = vortex_ring_velocity(R, G, p, 0.01 * R * R), exact = vortex_ring_velocity(R, G, p, 0.0);
    // the core's factor d^2 / (d^2 + c^2) is 1 - 0.002 here (d^2 about 5 R^2, c^2 = 0.01 R^2)
    EXPECT_LT((cored - exact).norm(), 0.003 * exact.norm()) << rho;
    if (rho < 1e-3) EXPECT_LT(std::abs(cored.x()), 1e-3 * std::abs(cored.z())) << rho;
  }
}

// Far from the ring its field is a dipole with an octupole correction: the error falls as (R/r)^4.
TEST(VortexRing, FarAwayTheMultipoleTermsGiveTheFieldToTheFourthPowerOfRadiusOverDistance) {
  const double R = 2.0, G = 3.0;
  for (double r : {7.0, 10.0, 20.0})
    for (double theta : {0.0, 0.4, 1.0, M_PI / 2, 2.5, M_PI}) {
      const Vec3 p = r * R * Vec3(std::sin(theta) * std::cos(0.3), std::sin(theta) * std::sin(0.3), std::cos(theta));
      const Vec3 exact = vortex_ring_velocity(R, G, p, 0.0), far = vortex_ring_multipole_velocity(R, G, p);
      // the dipole's field on its axis is G R^2 / (2 r^3); the next term of the series, on the axis
      // G R^2 / (2 r^3) (15/8) (R/r)^4, bounds the error (with 20 % for the terms after it)
      const double dipole = G * R * R / (2.0 * std::pow(r * R, 3));
      EXPECT_LT((far - exact).norm(), 1.2 * 1.875 * std::pow(r, -4) * dipole) << r << " " << theta;
    }
}

// The wake's rings far from the point are summed as multipoles: the sum stays within 1e-3 v of
// the ring-by-ring sum of the exact fields, at the faces of an LRM domain and far down the wake,
// with and without the ground's image.
TEST(VortexCylinder, TheMultipolesOfTheFarRingsKeepTheExactSum) {
  const double spacing = 0.1, length = 40.0, core = 0.6;  // a core above the spacing (the class takes the larger)
  for (double V : {0.0, 10.0, 30.0})
    for (double ground : {std::numeric_limits<double>::infinity(), 2.0 * kR}) {
      VortexCylinderWake w(kR, kT, kRho, Vec3(-V, 0, 0), core, spacing, length);
      if (ground < std::numeric_limits<double>::infinity()) w.set_ground(ground);
      const double v = w.mean_induced(), ds = spacing * kR, g = 2.0 * v * ds;
      for (const Vec3& p : {Vec3(2.5 * kR, 1.0 * kR, -2.5 * kR), Vec3(-2.5 * kR, 2.5 * kR, 2.5 * kR), Vec3(0.3 * kR, -2.5 * kR, 1.9 * kR),
                            Vec3(w.wake_direction() * 20.0 * kR), Vec3(-15.0 * kR, 0, 0)}) {
        Vec3 exact = Vec3::Zero();
        for (int k = 0; k < static_cast<int>(std::ceil(length / spacing)); ++k) {
          const Vec3 c = (k + 0.5) * ds * w.wake_direction();
          if (c.z() >= ground) continue;
          exact += vortex_ring_velocity(kR, g, p - c, core * core);
          if (ground < std::numeric_limits<double>::infinity())
            exact += vortex_ring_velocity(kR, -g, p - Vec3(c.x(), c.y(), 2.0 * ground - c.z()), core * core);
        }
        const Vec3 u = w.velocity(p);
        EXPECT_LT((u - exact).norm(), 1e-3 * v)
            << V << " " << ground << " " << p.transpose() << ": " << u.transpose() << " vs " << exact.transpose();
      }
    }
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
