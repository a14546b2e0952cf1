// Walls in the LRM domain: a ground plane through the signed-distance interface, moving
// relative to the domain with moving-wall bounce-back and refill; hover in ground effect against the
// algebraic models. Quick variants at N = 32; the sweeps run with `ship_lrm sweep ground`.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

#include "lrm_test_config.hpp"
#include "ship_lrm/lrm/inflow_sweep.hpp"

using namespace ship_lrm;
using ship_lrm::Vec3;

namespace {
using lrm::test::quick_config;

double worst_deviation(lrm::LrmDomain& d, const Vec3& stream) {
  const lbm::Fields f = d.solver().fields();
  const double scale = d.units().dx() / d.units().dt();
  double worst = 0;
  for (size_t c = 0; c < f.rho.size(); ++c) {
    if (lbm::is_wall(static_cast<lbm::CellType>(d.solver().lattice().types()[c] & ~lbm::kGeneralBit))) continue;
    const Vec3 u(f.u[3 * c] * scale, f.u[3 * c + 1] * scale, f.u[3 * c + 2] * scale);
    EXPECT_TRUE(u.allFinite());
    worst = std::max(worst, (u - stream).norm());
  }
  return worst;
}

// A uniform stream over the ground 6 m below the hub, the ground moving with the stream (forward
// flight at the stream's speed over ground at rest), the flow started.
std::shared_ptr<lrm::GroundPlane> add_ground_moving_with(lrm::LrmDomain& d, const Vec3& stream) {
  d.set_stream(stream);
  auto ground = std::make_shared<lrm::GroundPlane>(6.0);
  lrm::RigidMotion m;
  m.velocity = stream;
  ground->set_motion(m);
  d.add_wall(ground);
  d.restart_flow();
  return ground;
}

// v_IGE / v_OGE of the isolated rotor at 15 m/s with the rotor's far field at the faces, at z/R 0.5,
// 0.6 and 0.8 (the forward ground sweep's quick variant).
std::vector<double> forward_ratios_at_15_metres_per_second(lrm::LrmConfig base) {
  base.rotor_far_field = true;
  lrm::IsolatedRotorCase c;
  c.speed = 15.0;
  c.settle = 3.0;
  c.average = 1.0;
  const lrm::LrmConfig cfg = lrm::config_for_stream(base, c.speed);
  const double oge = lrm::run_isolated_rotor(cfg, c).induced_mean;
  std::vector<double> ratio;
  for (double z_over_R : {0.5, 0.6, 0.8}) {
    c.ground_height = z_over_R * cfg.radius;
    ratio.push_back(lrm::run_isolated_rotor(cfg, c).induced_mean / oge);
  }
  return ratio;
}

TEST(Ground, StreamOverGroundMovingWithItStaysUniformWhileTheGroundMoves) {
  // Forward flight over the ground without a rotor: the ground passes at the stream's speed, so the
  // moving-wall bounce-back must not disturb the stream. Then the rotorcraft sinks by 2.5 cells and
  // climbs back, so cells turn into walls and back into fluid: two layers at once, refilled front by
  // front. The stream must stay uniform to 0.5 %.
  // Known defect (docs/design.md): where the inflow face meets the moving ground under a uniform
  // stream, a grid-scale checkerboard mode grows (BGK at tau - 1/2 ~ 4e-6 and no strain for
  // Smagorinsky to act on). At 15 m/s it diverges after ~300 steps; at 5 m/s it reaches 0.9 % after
  // 800 steps. The run here is 5 m/s and 600 steps, so the check covers the wall motion and the
  // refill, not that corner. With a rotor the sweeps no longer diverge, but from ~12 m/s the
  // mode still covers the ground (docs/benchmarks.md at 193c1b4, 2026-11-24).
  lrm::LrmDomain d(quick_config());
  const Vec3 stream(-5.0, 0.0, 0.0);
  const auto ground = add_ground_moving_with(d, stream);
  EXPECT_GT(d.wall_cells(), 0u);
  d.step(300);
  EXPECT_LT(worst_deviation(d, stream), 0.005 * stream.norm());
  const std::size_t before = d.wall_cells();
  ground->set_pose(6.0 - 2.5 * d.units().dx(), Vec3::UnitZ());
  d.update_walls();
  EXPECT_GT(d.wall_cells(), before);
  EXPECT_EQ(d.rebuilds(), 2u);  // the first add_wall and this one
  d.step(200);
  ground->set_pose(6.0, Vec3::UnitZ());
  d.update_walls();
  EXPECT_EQ(d.wall_cells(), before);
  EXPECT_LT(worst_deviation(d, stream), 0.005 * stream.norm());  // the refilled layers
  d.step(100);
  EXPECT_LT(worst_deviation(d, stream), 0.005 * stream.norm());
}

// The mean velocity along x (m/s) in the first fluid layer above a level ground, over the middle half
// of the domain in x and y (away from the faces' corners).
double speed_above_ground(lrm::LrmDomain& d) {
  const lbm::Lattice& lat = d.solver().lattice();
  const lbm::Fields f = d.solver().fields();
  const int n = d.cells_per_edge();
  const auto wall = [&](int i, int j, int k) { return lbm::is_wall(lat.type(i, j, k)); };
  int k = n - 1;
  while (k > 0 && wall(n / 2, n / 2, k - 1)) --k;  // k - 1: the first fluid layer above the ground at the centre
  double sum = 0;
  int count = 0;
  for (int j = n / 4; j < 3 * n / 4; ++j)
    for (int i = n / 4; i < 3 * n / 4; ++i) {
      EXPECT_FALSE(wall(i, j, k - 1));
      EXPECT_TRUE(wall(i, j, k));
      sum += f.u[3 * lat.index(i, j, k - 1)];
      ++count;
    }
  return sum / count * d.units().dx() / d.units().dt();
}
}  // namespace

TEST(Ground, ASlipGroundLeavesTheStreamAlongItUndisturbed) {
  // A stream along a ground at rest relative to the domain (a wind tunnel's floor). A free-slip wall
  // reflects specularly and takes no momentum along itself, so the stream stays uniform next to it, as
  // over the inviscid ground of the image models (Cheeseman & Bennett); a no-slip wall slows the
  // layer above it (a boundary layer grows from the inflow face).
  const Vec3 stream(-5.0, 0.0, 0.0);
  const auto run = [&](bool slip) {
    lrm::LrmDomain d(quick_config());
    d.set_stream(stream);
    auto ground = std::make_shared<lrm::GroundPlane>(6.0);
    ground->set_slip(slip);
    d.add_wall(ground);
    d.restart_flow();
    EXPECT_GT(d.wall_cells(), 0u);
    d.step(300);
    return std::make_pair(speed_above_ground(d), worst_deviation(d, stream));
  };
  const auto [slip_speed, slip_worst] = run(true);
  const auto [no_slip_speed, no_slip_worst] = run(false);
  EXPECT_LT(slip_worst, 0.005 * stream.norm());
  EXPECT_NEAR(slip_speed, stream.x(), 0.005 * stream.norm());
  EXPECT_GT(no_slip_speed, stream.x() + 0.05 * stream.norm());  // slower than the stream by more than 5 %
  std::printf("layer above the ground: slip %.4f m/s, no slip %.4f m/s (stream %.1f); worst deviation slip %.2e, no slip %.2e m/s\n",
              slip_speed, no_slip_speed, stream.x(), slip_worst, no_slip_worst);
}

TEST(Ground, ASlipGroundMaySlideAlongItselfOnly) {
  // Forward flight over a slip ground: the ground passes under the rotor along itself, which specular
  // reflection leaves alone. Moving across itself (a sinking rotorcraft) or turning, it would need the
  // normal velocity a slip wall does not impose: refused, and the domain keeps its walls.
  lrm::LrmDomain d(quick_config());
  auto ground = std::make_shared<lrm::GroundPlane>(6.0);
  ground->set_slip(true);
  lrm::RigidMotion m;
  m.velocity = Vec3(-20.0, 3.0, 0.0);
  ground->set_motion(m);
  d.add_wall(ground);
  const std::size_t cells = d.wall_cells();
  EXPECT_GT(cells, 0u);
  EXPECT_TRUE(d.solver().lattice().wall_motions().empty());  // built at rest: no moving-wall slot
  m.velocity = Vec3(-20.0, 0.0, 0.5);
  ground->set_motion(m);
  EXPECT_THROW(d.update_wall_motions(), ship_lrm::ConfigError);
  m.velocity = Vec3::Zero();
  m.omega = Vec3(0.0, 0.1, 0.0);
  ground->set_motion(m);
  EXPECT_THROW(d.update_walls(), ship_lrm::ConfigError);
  EXPECT_EQ(d.wall_cells(), cells);
  lrm::LrmDomain e(quick_config());
  auto kept_clear = std::make_shared<lrm::GroundPlane>(6.0);
  kept_clear->set_slip(true);
  kept_clear->set_clear_of_faces(true);  // the held air inside would not slide with it
  EXPECT_THROW(e.add_wall(kept_clear), ship_lrm::ConfigError);
  EXPECT_EQ(e.wall_cells(), 0u);
  lrm::IsolatedRotorCase c;
  c.slip_ground = true;  // without a ground
  EXPECT_THROW(lrm::run_isolated_rotor(quick_config(), c), ship_lrm::ConfigError);
}

TEST(Ground, BadSetUpsAreRefusedBeforeAnyStep) {
  lrm::LrmDomain d(quick_config());
  EXPECT_THROW(d.add_wall(std::make_shared<lrm::GroundPlane>(0.0)), ship_lrm::ConfigError);  // through the disk
  lrm::IsolatedRotorCase c;
  c.ground_height = 40.0;  // below the bottom face at a = 1.25 (12.3 m)
  EXPECT_THROW(lrm::run_isolated_rotor(quick_config(), c), ship_lrm::ConfigError);
  EXPECT_THROW(lrm::check_isolated_rotor(quick_config(), c), ship_lrm::ConfigError);  // what the sweeps ask first
  c.ground_height = 0.01;                                                             // on the disk's cells
  EXPECT_THROW(lrm::check_isolated_rotor(quick_config(), c), lrm::WallOnRotorDisk);
  c.ground_height = 0.5 * 4.92;
  EXPECT_NO_THROW(lrm::check_isolated_rotor(quick_config(), c));
  EXPECT_THROW(lrm::GroundPlane(1.0, Vec3::Zero()), std::invalid_argument);
}

TEST(Ground, HoverAtHalfARadiusLiesBetweenCheesemanBennettAndHayden) {
  // ground-effect target, quick variant (N = 32): the thesis' LRM matched the algebraic models for
  // 0.5 < z/R < 0.6 (fig. 8.9); at z/R = 0.5 the ratio must lie between Hayden (0.625) and
  // Cheeseman-Bennett (0.75). Higher above the ground the LRM still fails (docs/benchmarks.md at 193c1b4).
  lrm::IsolatedRotorCase c;
  c.settle = 3.0;
  c.average = 1.5;
  std::vector<double> done;  // the progress reported on the way: rising to 1 (the sweeps' progress line)
  c.progress = [&done](double f) { done.push_back(f); };
  const auto oge = lrm::run_isolated_rotor(quick_config(), c);
  ASSERT_GE(done.size(), 80u);  // about every 0.05 s of 4.5 s
  EXPECT_GT(done.front(), 0.0);
  EXPECT_TRUE(std::is_sorted(done.begin(), done.end()));
  EXPECT_DOUBLE_EQ(done.back(), 1.0);
  c.progress = nullptr;
  c.ground_height = 0.5 * quick_config().radius;
  const auto ige = lrm::run_isolated_rotor(quick_config(), c);
  const double ratio = ige.induced_mean / oge.induced_mean;
  EXPECT_GT(ratio, lrm::hayden_ratio(0.5));
  EXPECT_LT(ratio, lrm::cheeseman_bennett_ratio(0.5, 0.0, 1.0));
}

TEST(Ground, HoverWithEntrainingFacesStaysBelowOneWhereTheThesisFailed) {
  // ground-effect target, quick variant (N = 32, a = 1.25). The thesis' LRM (fig. 8.9), and this one
  // with the thesis' faces, put v_IGE / v_OGE above 1 from z/R = 0.8 up (N = 32: 1.077 at z/R = 1):
  // the velocity side faces hold still air, a wall for the ground's wall jet, which turns up along
  // them and comes back into the rotor (docs/benchmarks.md at 193c1b4, 2026-12-02). With entraining pressure
  // faces the jet leaves at the ambient pressure and the air drawn in comes from rest; up to z/R = 1
  // the ratio must then rise with height and stay below 1, as both algebraic models do (measured
  // 0.78, 0.83, 0.91 here; N = 64 with 30 s averages: 0.76, 0.93, 0.98). Higher up it is still not
  // right (N = 64: 1.01 - 1.02 from z/R = 1.25; at a = 2 the same with either faces), so the test
  // stops at 1.
  lrm::LrmConfig cfg = quick_config();
  cfg.faces.fill(lbm::FaceType::PressureOutlet);
  cfg.entraining_pressure_faces = true;
  lrm::IsolatedRotorCase c;
  c.settle = 3.0;
  c.average = 2.0;
  const double oge = lrm::run_isolated_rotor(cfg, c).induced_mean;
  std::vector<double> ratio;
  for (double z_over_R : {0.6, 0.8, 1.0}) {
    c.ground_height = z_over_R * cfg.radius;
    ratio.push_back(lrm::run_isolated_rotor(cfg, c).induced_mean / oge);
    RecordProperty("ratio_at_z_over_R_" + std::to_string(static_cast<int>(std::lround(10 * z_over_R))) + "_tenths",
                   std::to_string(ratio.back()));
  }
  EXPECT_LT(ratio[0], ratio[1]);
  EXPECT_LT(ratio[1], ratio[2]);
  EXPECT_LT(ratio[2], 1.0);
  // all-pressure faces hold air at rest only: a stream is refused
  lrm::LrmDomain d(cfg);
  EXPECT_THROW(d.set_stream(Vec3(-5.0, 0, 0)), ship_lrm::ConfigError);
}

TEST(Ground, ForwardFlightAt6MetresPerSecondHasAGroundEffectThatFadesWithHeight) {
  // ground-effect target, quick variant (N = 32): the thesis' LRM predicted no ground effect at all
  // in forward flight (fig. 8.11). Physics asks for two things at low speed (6 m/s, V / v_h = 0.5,
  // where Cheeseman-Bennett gives 0.81 at z/R = 0.5 and 0.95 at z/R = 1): the inflow is reduced
  // (ratio below 1) and the reduction fades with height (the thesis, 8.2.3: a monotonically
  // increasing inflow). 15 m/s: the next test.
  lrm::IsolatedRotorCase c;
  c.speed = 6.0;
  c.settle = 3.0;
  c.average = 1.5;
  const lrm::LrmConfig cfg = lrm::config_for_stream(quick_config(), c.speed);
  const auto oge = lrm::run_isolated_rotor(cfg, c);
  c.ground_height = 0.5 * cfg.radius;
  const double low = lrm::run_isolated_rotor(cfg, c).induced_mean / oge.induced_mean;
  c.ground_height = 1.0 * cfg.radius;
  const double high = lrm::run_isolated_rotor(cfg, c).induced_mean / oge.induced_mean;
  EXPECT_LT(low, high);
  EXPECT_LT(high, 1.0);
}

TEST(Ground, ForwardFlightAt15MetresPerSecondRisesMonotonicallyWithHeightAtTheSweepsLatticeVelocity) {
  // ground-effect target, quick variant (N = 32) at 15 m/s, where Cheeseman-Bennett's ratio rises
  // with height (0.945, 0.962, 0.979 at z/R 0.5, 0.6, 0.8). At the thesis' lattice velocity (30 m/s)
  // a grid-scale mode from the corner where the inflow face meets the moving ground made the LRM's
  // jump about (0.43, 1.03, 0.60 with the rotor's far field at the faces; this test fails there); at
  // the forward ground sweep's lattice velocity (kForwardGroundLatticeVelocity, half the Mach number)
  // it must rise with height and stay below 1 (measured 0.70, 0.77, 0.83: steps of 0.06 - 0.07, the
  // ratios' uncertainty from the averaging window 0.003).
  lrm::LrmConfig base = quick_config();
  base.reference_velocity = lrm::kForwardGroundLatticeVelocity;
  const std::vector<double> ratio = forward_ratios_at_15_metres_per_second(base);
  EXPECT_LT(ratio[0], ratio[1]);
  EXPECT_LT(ratio[1], ratio[2]);
  EXPECT_LT(ratio[2], 1.0);
}

TEST(Ground, StreamAt15MetresPerSecondOverTheMovingGroundStaysUniformWithAnAbsorbingInflowLayer) {
  // The known defect of the first test at 15 m/s: where the inflow face meets the moving ground a
  // grid-scale mode grows (85 % of the stream after 600 steps, measured). The absorbing layer
  // (LrmConfig::absorbing_layer, 4 cells) must keep the stream uniform to 0.5 % for 1 000 steps, as
  // without the ground (measured: 0.18 % with the layer, 0.15 % without the ground; the largest
  // deviation then sits at the top face, not at the corner).
  lrm::LrmConfig cfg = quick_config();
  cfg.absorbing_layer = 4;
  lrm::LrmDomain d(cfg);
  const Vec3 stream(-15.0, 0.0, 0.0);
  add_ground_moving_with(d, stream);
  d.step(1000);
  EXPECT_LT(worst_deviation(d, stream), 0.005 * stream.norm());
}

TEST(Ground, ForwardFlightAt15MetresPerSecondRisesMonotonicallyWithHeightAtTheThesisLatticeVelocityWithAnAbsorbingLayer) {
  // The previous test at the thesis' lattice velocity (30 m/s, where the ratios jumped about: 0.96,
  // 0.55, 1.05 at z/R 0.5, 0.6, 0.8, measured) with the absorbing inflow layer of 4 cells: they must
  // rise with height and stay below 1, like Cheeseman-Bennett's (measured 0.717, 0.813, 0.861; at
  // lattice velocity 60 without the layer 0.680, 0.803, 0.831).
  lrm::LrmConfig base = quick_config();
  base.absorbing_layer = 4;
  const std::vector<double> ratio = forward_ratios_at_15_metres_per_second(base);
  EXPECT_LT(ratio[0], ratio[1]);
  EXPECT_LT(ratio[1], ratio[2]);
  EXPECT_LT(ratio[2], 1.0);
}

TEST(Fuselage, VoxelisedVolumeMatchesTheShapeAndItStaysBelowTheDisk) {
  // The body fixed to the domain: cells inside the signed-distance shape become walls. Their volume
  // must match the shape's (Monte-Carlo integral of the same distance function) to 10 % at N = 64.
  lrm::LrmConfig c = quick_config();
  c.nodes = 64;
  lrm::LrmDomain d(c);
  auto body = std::make_shared<lrm::Fuselage>();
  d.add_wall(body);
  const double dx = d.units().dx();
  const double voxels = static_cast<double>(d.wall_cells()) * dx * dx * dx;
  std::uint64_t state = 12345, inside = 0;
  const int samples = 400000;
  const Vec3 lo(-6.5, -1.0, -0.5), hi(2.6, 1.0, 2.4);
  auto uniform = [&]() {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(state >> 11) / 9007199254740992.0;
  };
  for (int k = 0; k < samples; ++k) {
    const Vec3 p(lo.x() + (hi.x() - lo.x()) * uniform(), lo.y() + (hi.y() - lo.y()) * uniform(), lo.z() + (hi.z() - lo.z()) * uniform());
    if (body->signed_distance(p) < 0) ++inside;
  }
  const double volume = (hi - lo).prod() * inside / samples;
  EXPECT_GT(volume, 5.0);  // cabin and boom, m^3
  EXPECT_NEAR(voxels, volume, 0.10 * volume);
  EXPECT_GT(body->signed_distance(Vec3::Zero()), 0.5);  // the hub is clear of the body
}
