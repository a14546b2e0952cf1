// LRM domain, isolated rotor (issue 4, thesis 8.1): a uniform stream stays uniform; the inflow of a
// uniformly loaded rotor against momentum theory (Glauert) in forward flight. Quick variants at
// N = 32; the full sweeps run with `ship_lrm sweep inflow`.
#include <gtest/gtest.h>

#include <cmath>

#include "ship_lrm/lrm/domain.hpp"
#include "ship_lrm/rotor/momentum_theory.hpp"

using namespace ship_lrm;

namespace {
lrm::LrmConfig quick_config() {
  lrm::LrmConfig c;
  c.nodes = 32;
  c.reach = 1.25;
  c.backend = lbm::Backend::Cpu;
  return c;
}
}  // namespace

class UniformStream : public ::testing::TestWithParam<std::array<double, 3>> {};

TEST_P(UniformStream, StaysUniformThroughTheOpenFaces) {
  // Issue 4, acceptance 3 (translating domain, body-frame formulation: the motion is the stream at
  // the faces): to 0.5 % of the stream speed after 1000 steps, in every fluid cell.
  lrm::LrmDomain d(quick_config());
  const auto s = GetParam();
  const rotor::Vec3 stream(s[0], s[1], s[2]);
  d.set_stream(stream);
  d.restart_flow();
  d.step(1000);
  const lbm::Fields f = d.solver().fields();
  const double scale = d.units().dx() / d.units().dt();
  double worst = 0;
  for (size_t c = 0; c < f.rho.size(); ++c) {
    const rotor::Vec3 u(f.u[3 * c] * scale, f.u[3 * c + 1] * scale, f.u[3 * c + 2] * scale);
    worst = std::max(worst, (u - stream).norm());
  }
  EXPECT_LT(worst, 0.005 * stream.norm()) << "largest deviation " << worst << " m/s";
}

INSTANTIATE_TEST_SUITE_P(Streams, UniformStream,
                         ::testing::Values(std::array<double, 3>{-30, 0, 0}, std::array<double, 3>{-20, 6, 0},
                                           std::array<double, 3>{-10, -3, 0}));

TEST(LrmDomain, BadInputIsRejectedBeforeAnyStep) {
  auto c = quick_config();
  c.reach = 0.9;
  EXPECT_THROW(lrm::LrmDomain{c}, lbm::ConfigError);
  c = quick_config();
  c.nodes = 8;
  EXPECT_THROW(lrm::LrmDomain{c}, lbm::ConfigError);
  lrm::LrmDomain d(quick_config());
  EXPECT_THROW(d.set_stream(rotor::Vec3(-200, 0, 0)), lbm::ConfigError);  // beyond the lattice Mach limit
}
