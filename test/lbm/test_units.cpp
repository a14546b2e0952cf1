// Unit conversion against the thesis' tables 6.2-6.4.
#include <gtest/gtest.h>

#include "ship_lrm/lbm/lattice.hpp"
#include "ship_lrm/lbm/units.hpp"

using namespace ship_lrm::lbm;
using ship_lrm::ConfigError;

// Thesis 6.4 / table 6.4: LRM, 4R = 4 x 4.92 m, N = 64, u_ref = 30 m/s at 0.3/sqrt(3):
// time step 1.80352 ms.
TEST(Units, LrmTimeStepMatchesThesis) {
  UnitReference r;
  r.length = 4 * 4.92;
  r.nodes = 64;
  r.velocity = 30.0;
  r.viscosity = 1.46072e-4;
  r.density = 1.1934;
  const UnitConverter u(r);
  EXPECT_NEAR(u.dt() * 1e3, 1.80352, 1e-4);
  EXPECT_NEAR(u.mach_number(), 0.3, 1e-9);
  EXPECT_NEAR(u.to_lattice_velocity(30.0), 0.3 / std::sqrt(3.0), 1e-12);
  EXPECT_NEAR(u.to_physical_velocity(u.to_lattice_velocity(12.3)), 12.3, 1e-12);
  EXPECT_GT(u.relaxation_time(), 0.5);
}

TEST(Units, RejectsBadReferences) {
  UnitReference r;
  r.lattice_velocity = 0.3;  // Mach 0.52
  EXPECT_THROW(UnitConverter{r}, ConfigError);
  r = UnitReference{};
  r.viscosity = -1;
  EXPECT_THROW(UnitConverter{r}, ConfigError);
  r = UnitReference{};
  r.nodes = 2;
  EXPECT_THROW(UnitConverter{r}, ConfigError);
}
