// The statistics users compare with wind tunnels: Reynolds stresses of known signals, probe frames and
// files, the nesting of the NRC deck case's resolutions, and a nested precompute with probes: its
// fine level served with no seam, its probes in the fluid or refused before any step.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "nrc_model_case.hpp"
#include "ship_lrm/lbm/lattice.hpp"
#include "ship_lrm/wake/nested_table.hpp"
#include "ship_lrm/wake/nrc_deck.hpp"
#include "ship_lrm/wake/probe_points.hpp"
#include "ship_lrm/wake/wake_precompute.hpp"
#include "ship_lrm/wake/wake_statistics.hpp"
#include "temp_path.hpp"

using namespace ship_lrm::wake;
using ship_lrm::ConfigError;
namespace fs = std::filesystem;

namespace {

std::string temp(const std::string& name) { return ship_lrm::test::temp_path("ship_lrm_test_statistics", name); }

constexpr double kPi = 3.14159265358979323846;

// u = U + a sin(w t), v = b sin(w t + phi), w = c: over whole periods the mean is (U, 0, c), u'u' = a^2/2,
// v'v' = b^2/2, u'v' = a b cos(phi) / 2, the rest 0.
struct Signal {
  double U = -9.77, a = 1.2, b = 0.8, phi = 0.6, c = 0.3, omega = 2 * kPi * 5.0;
  std::array<float, 3> at(double t) const {
    return {static_cast<float>(U + a * std::sin(omega * t)), static_cast<float>(b * std::sin(omega * t + phi)), static_cast<float>(c)};
  }
};

}  // namespace

TEST(WakeStatistics, ReynoldsStressesOfAKnownSignal) {
  const Signal s;
  ProbeSeries series;
  series.points = {{0, 0, 0}, {1, 0, 0}};
  const int n = 1000;  // 10 periods of 100 samples
  for (int k = 0; k < n; ++k) {
    const double t = k * 0.002;
    series.time.push_back(t);
    const auto v = s.at(t);
    for (int p = 0; p < 2; ++p)
      for (int d = 0; d < 3; ++d) series.u.push_back(p == 0 ? v[d] : NAN);  // probe 1 never in the fluid
  }
  const auto st = series.statistics(0);
  EXPECT_EQ(st.samples, n);
  EXPECT_NEAR(st.mean[0], s.U, 1e-5);
  EXPECT_NEAR(st.mean[1], 0.0, 1e-5);
  EXPECT_NEAR(st.mean[2], s.c, 1e-6);
  EXPECT_NEAR(st.stress[0], s.a * s.a / 2, 1e-5);
  EXPECT_NEAR(st.stress[1], s.b * s.b / 2, 1e-5);
  EXPECT_NEAR(st.stress[2], 0.0, 1e-6);
  EXPECT_NEAR(st.stress[3], s.a * s.b * std::cos(s.phi) / 2, 1e-5);
  EXPECT_NEAR(st.tke, (s.a * s.a + s.b * s.b) / 4, 1e-5);
  EXPECT_EQ(series.statistics(1).samples, 0);
  EXPECT_TRUE(std::isnan(series.statistics(1).tke));
  // the same signal at every point of a plane, overall and in one phase ensemble
  CentrePlaneStats plane;
  PlaneSample p;
  p.nx = 2;
  p.nz = 1;
  p.x = {0.0, 1.0};
  p.z = {0.0};
  p.solid = {0, 0};
  for (int k = 0; k < n; ++k) {
    const auto v = s.at(k * 0.002);
    p.u = {v[0], v[1], v[2], v[0], v[1], v[2]};
    plane.add(p, -1);
    if (k % 2 == 0) plane.add(p, 2);
  }
  const auto r = plane.stress();
  EXPECT_NEAR(r[6 + 0], s.a * s.a / 2, 1e-5);
  EXPECT_NEAR(r[6 + 3], s.a * s.b * std::cos(s.phi) / 2, 1e-5);
  EXPECT_NEAR(plane.tke()[1], (s.a * s.a + s.b * s.b) / 4, 1e-5);
  EXPECT_EQ(plane.phase_samples[2], n / 2);
  EXPECT_NEAR(plane.tke(2)[0], (s.a * s.a + s.b * s.b) / 4, 1e-5);
  // a run shorter than the period has phases without samples: written as nan, not read past the end
  const std::string csv = temp("phases.csv");
  write_plane_csv(csv, plane, true, 9.77);
  std::ifstream in(csv);
  std::string header, row;
  std::getline(in, header);
  std::getline(in, row);
  EXPECT_NE(header.find("phase0_u"), std::string::npos);
  EXPECT_NE(row.find("nan"), std::string::npos);
}

// The wind-tunnel frame (thesis 7.1): x aft, y starboard, z up from the bottom of the hangar door; the
// ship frame x forward, z down; model-scale probes on a full-scale run scale by 50.
TEST(WakeStatistics, ProbeFramesAndFiles) {
  const auto s = to_ship_frame({0.3, 0.06, 0.07}, ProbeFrame::Tunnel);
  EXPECT_DOUBLE_EQ(s[0], -0.3);
  EXPECT_DOUBLE_EQ(s[1], 0.06);
  EXPECT_DOUBLE_EQ(s[2], -0.07);
  const auto full = to_ship_frame({0.3, 0.06, 0.07}, ProbeFrame::Tunnel, 1.0 / 50.0);
  EXPECT_NEAR(full[0], -15.0, 1e-12);
  const auto back = from_ship_frame(full, ProbeFrame::Tunnel, 1.0 / 50.0);
  EXPECT_NEAR(back[2], 0.07, 1e-12);
  EXPECT_THROW(parse_probe_frame("body"), ConfigError);
  const std::string good = temp("probes.csv");
  std::ofstream(good) << "# thesis 7.1\nx,y,z\n0.3,0,0.07\n\n0.3, 0.06 ,0.07\n";
  const auto pts = read_probe_csv(good);
  ASSERT_EQ(pts.size(), 2u);
  EXPECT_DOUBLE_EQ(pts[1][1], 0.06);
  const auto refused = [](const std::string& text) {
    const std::string path = temp("bad_probes.csv");
    std::ofstream(path) << text;
    EXPECT_THROW(read_probe_csv(path), ConfigError) << text;
  };
  refused("x,y,z\n");                // no points
  refused("0.3,0\n");                // two numbers
  refused("0.3,0,0.07,1\n");         // four
  refused("0.3,0,0.07\n0.3,a,1\n");  // a word after the first row
  refused("0.3,0,inf\n");
  const std::string folder = temp("a_folder");
  fs::create_directories(folder);
  EXPECT_THROW(read_probe_csv(folder), ConfigError);
  EXPECT_THROW(read_probe_csv(temp("missing.csv")), ConfigError);
}

// 364 cells per ship length over the deck nest as 52 x 7, 546 as 78 x 7 (the coarse resolution nearest
// 52 with a ratio from 2 to 8); a resolution that has no such split is refused.
TEST(WakeStatistics, NrcDeckResolutionsNest) {
  EXPECT_EQ(nest_resolution(364), (std::array<int, 2>{52, 7}));
  EXPECT_EQ(nest_resolution(546), (std::array<int, 2>{78, 7}));
  EXPECT_EQ(nest_resolution(64), (std::array<int, 2>{32, 2}));
  EXPECT_THROW(nest_resolution(23), ConfigError);
  EXPECT_THROW(nest_resolution(997), ConfigError);  // a prime: no ratio from 2 to 8 divides it
}

// A probe fixed to a heaving ship records the air relative to itself: its vertical velocity is the
// air's (as a probe fixed in the mean frame there records it) plus the heave rate, A w cos(w t) for a
// heave of A sin(w t) upwards (0.04 m at 1 Hz on the model, thesis 7.2; z points down). Ahead of the
// bow, where the probe's 0.04 m of travel crosses no gradient to speak of.
TEST(WakeStatistics, AShipFixedProbeRecordsTheAirRelativeToTheShip) {
  PrecomputeOptions o = ship_lrm::test::nrc_model_case("heave", 32);
  o.startup = 0.3;
  o.duration = 1.0;  // one period
  o.frame_interval = 1.0;
  o.stats_interval = 0.005;
  o.probes = {{3.2, 0.0, -0.3}};  // 0.7 m ahead of the stem (x = 2.5 m), 0.3 m above the deck's level
  o.probes_on_ship = true;
  o.out = temp("ship_probe.h5");
  const PrecomputeResult on = precompute_wake(o);
  o.probes_on_ship = false;
  o.out = temp("mean_probe.h5");
  const PrecomputeResult fixed = precompute_wake(o);
  ASSERT_EQ(on.probes.time, fixed.probes.time);
  const double A = 0.04, w = 2 * kPi;
  double sum2 = 0;
  for (std::size_t k = 0; k < on.probes.time.size(); ++k) {
    const double expected = fixed.probes.u[3 * k + 2] + A * w * std::cos(w * on.probes.time[k]);
    sum2 += std::pow(on.probes.u[3 * k + 2] - expected, 2);
    EXPECT_NEAR(on.probes.u[3 * k], fixed.probes.u[3 * k], 0.01 * 9.77);
  }
  EXPECT_LT(std::sqrt(sum2 / on.probes.time.size()), 0.05 * A * w);  // the heave rate's amplitude is 0.25 m/s
  EXPECT_GT(on.probes.statistics(0).stress[2], 0.8 * 0.5 * A * A * w * w);
}
