// The free vortex-ring wake of a uniformly loaded actuator disk (rotor/free_wake_disk.hpp) against the
// two exact results for such a disk: in axial flow its mean induced velocity is momentum theory's
// (Froude's theorem holds exactly for a uniform pressure jump), and in fast edgewise flight it is a
// wing with elliptic span loading, whose mean downwash is T / (2 rho A V) (Prandtl), Glauert's limit.
// Coarse numerics keep each case to seconds; docs/benchmarks.md at 193c1b4 has the converged runs.
#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>
#include <vector>

#include "ship_lrm/rotor/free_wake_disk.hpp"
#include "ship_lrm/rotor/momentum_theory.hpp"

using namespace ship_lrm::rotor;
using ship_lrm::Vec3;

namespace {
FreeWakeDiskConfig coarse(const Vec3& air_over_vh) {
  FreeWakeDiskConfig c;
  c.radius = 4.92, c.thrust = 24525, c.density = 1.1934;
  c.air = air_over_vh * hover_induced_velocity(c.thrust, c.density, c.radius);
  c.ring_points = 32, c.step = 0.05, c.core = 0.05, c.edge_points = 128;
  c.wake_age = 5.0, c.settle = 1.0, c.average = 1.0;
  return c;
}
}  // namespace

TEST(FreeWakeDisk, InAClimbTheMeanInducedVelocityIsMomentumTheorys) {
  // climb at V_c = v_h: v = -V_c / 2 + sqrt(V_c^2 / 4 + v_h^2) = 0.618 v_h
  auto c = coarse(Vec3(0, 0, 1.0));
  std::vector<double> done, means;  // the progress reported at every sample (the sweep's progress line)
  c.progress = [&](double f, double mean) { done.push_back(f), means.push_back(mean); };
  const auto r = solve_free_wake_disk(c);
  ASSERT_EQ(done.size(), r.history.size());
  for (std::size_t k = 0; k < means.size(); ++k) EXPECT_EQ(means[k], r.history[k].mean);
  EXPECT_TRUE(std::is_sorted(done.begin(), done.end()));
  EXPECT_DOUBLE_EQ(done.back(), 1.0);
  // work counted as rings^2: the first tenth of the time (the wake still short) is far less of the work
  EXPECT_LT(done[done.size() / 10], 0.05);
  EXPECT_NEAR(r.momentum / r.hover, 0.5 * (std::sqrt(5.0) - 1.0), 1e-9);
  EXPECT_NEAR(r.mean / r.momentum, 1.0, 0.01) << r.mean << " m/s against " << r.momentum;
  EXPECT_LT((r.max - r.min) / r.mean, 0.01);  // steady
}

TEST(FreeWakeDisk, InFastEdgewiseFlightTheMeanInducedVelocityIsGlauertsLimit) {
  auto c = coarse(Vec3(-4.0, 0, 0));     // V = 4 v_h: mu about 0.2 for the Bo 105
  set_wake_lengths(c, 0.05, 10.0, 2.0);  // rings 0.05 R apart (the core) along the faster wake, 10 R of it
  c.settle = 0.5, c.average = 0.5;       // it passes the disk in 0.5 R / v_h
  const auto r = solve_free_wake_disk(c);
  const double prandtl = r.hover / 4.0;           // T / (2 rho A V) = v_h^2 / V
  EXPECT_NEAR(r.momentum / prandtl, 1.0, 0.005);  // Glauert's formula is within 0.3 % of its limit there
  EXPECT_NEAR(r.mean / r.momentum, 1.0, 0.01) << r.mean << " m/s against " << r.momentum;
}

TEST(FreeWakeDisk, BadInputIsRefusedBeforeAnyStep) {
  auto c = coarse(Vec3(-1.0, 0, 0));
  auto refused = [](FreeWakeDiskConfig x) { EXPECT_THROW(solve_free_wake_disk(x), std::invalid_argument); };
  FreeWakeDiskConfig x = c;
  x.ring_points = 4, refused(x);
  x = c, x.step = 0, refused(x);
  x = c, x.core = 0, refused(x);
  x = c, x.radius = -1, refused(x);
  x = c, x.air = Vec3(0, 0, std::nan("")), refused(x);
  x = c, x.wake_age = 0.1, refused(x);
  x = c, x.air = Vec3(-1.0, 0, -0.5) * hover_induced_velocity(c.thrust, c.density, c.radius), refused(x);  // a descent
}
