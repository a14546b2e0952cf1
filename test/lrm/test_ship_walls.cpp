// The ship as a wall of the LRM domain (the ship walls "from the same geometry and
// motion"): its velocity relative to the moving, turning grid must be the rigid-body velocity that
// finite differences of its points' positions give, and a ship at rest in the air must leave a
// uniform stream through a translating and rotating domain uniform (no-slip walls moving with the
// fluid, re-voxelised as they cross the grid, disturb nothing; uniform-stream bound's 0.5 %).
#include <gtest/gtest.h>

#include "ship_lrm/lrm/ship_walls.hpp"

using namespace ship_lrm;
using Eigen::Vector3d;

namespace {
// The domain's pose at time t: hub moving at v, axes turning at omega (mr axes) from R0.
lrm::DomainPose pose_at(double t, const Vector3d& hub0, const Mat3& R0, const Vector3d& v, const Vector3d& omega) {
  lrm::DomainPose p;
  p.hub = hub0 + v * t;
  const double a = omega.norm() * t;
  p.rotation = R0 * (a > 0 ? Eigen::AngleAxisd(a, omega.normalized()).toRotationMatrix() : Mat3::Identity());
  p.hub_velocity = v;
  p.omega = omega;
  return p;
}
}  // namespace

TEST(ShipWall, VelocityRelativeToTheGridIsTheDerivativeOfItsPointsPositions) {
  std::shared_ptr<const wake::ShipGeometry> ship = wake::make_natogd(1.0);
  std::shared_ptr<const wake::ShipMotion> motion = wake::make_motion("approach", 1.0, wake::motion_centre(ship->datum()));
  lrm::ShipWall wall(ship, motion);
  const Vector3d hub0(-20, 1, -12), v(5, 0.5, -0.3), omega(0.02, -0.04, 0.06);
  const Mat3 R0 = (Eigen::AngleAxisd(0.2, Vector3d::UnitZ()) * Eigen::AngleAxisd(0.05, Vector3d::UnitY())).toRotationMatrix();
  const double t = 3.7, h = 1e-4;
  for (const Vector3d r : {Vector3d(3, -2, 4), Vector3d(-6, 5, 1), Vector3d(0, 0, 0)}) {
    wall.place(t, pose_at(t, hub0, R0, v, omega));
    const Vector3d body = wall.body_point(r);
    // the composition is the mean-frame placement of the ship
    const lrm::DomainPose p = pose_at(t, hub0, R0, v, omega);
    EXPECT_LT((body - motion->placement(t).to_body(p.to_mean(r))).norm(), 1e-12);
    EXPECT_DOUBLE_EQ(wall.signed_distance(r), ship->signed_distance(body));
    // where that body point is in the grid at t +- h
    auto grid_position = [&](double s) {
      const lrm::DomainPose q = pose_at(s, hub0, R0, v, omega);
      return Vector3d(q.rotation.transpose() * (motion->position(body, s) - q.hub));
    };
    const Vector3d fd = (grid_position(t + h) - grid_position(t - h)) / (2 * h);
    const lrm::RigidMotion m = wall.motion();
    const Vector3d u = m.velocity + m.omega.cross(r);
    EXPECT_LT((u - fd).norm(), 1e-6 * (1 + fd.norm())) << "r = " << r.transpose() << ": " << u.transpose() << " vs " << fd.transpose();
  }
}

namespace {
// Largest deviation (m/s) from the still air seen from the grid, over every fluid cell, after `steps`
// LBM steps of a domain whose hub starts `height` m above the landing spot and moves at v, turning at
// omega, past a NatoGD at rest in still air.
double disturbance(double height, const Vector3d& v, const Vector3d& omega, int steps, std::size_t* voxelisations, int nodes = 16) {
  lrm::LrmConfig cfg;
  cfg.nodes = nodes;
  cfg.reach = 1.25;
  cfg.backend = lbm::Backend::Cpu;
  lrm::LrmDomain domain(cfg);
  std::shared_ptr<const wake::ShipGeometry> ship = wake::make_natogd(1.0);
  std::shared_ptr<const wake::ShipMotion> still = std::make_shared<wake::StaticMotion>();
  lrm::ShipInDomain walls(ship, still);
  // hub 9.5 m above the deck over the landing spot: deck, hangar face and stern in the domain
  const Vector3d hub0(-12.75, 0, -height);
  const Mat3 R0 = Mat3::Identity();
  const double dt = domain.time_step();
  auto motion_at = [&](double t) {
    const lrm::DomainPose p = pose_at(t, hub0, R0, v, omega);
    lrm::LrmDomain::Motion m;
    m.air_velocity = -(p.rotation.transpose() * v);  // still air, seen from the hub
    m.omega = omega;
    // the hub's inertial acceleration in mr axes: d/dt (R^T v) + omega x (R^T v) = 0 for constant v
    return std::make_pair(p, m);
  };
  auto [p0, m0] = motion_at(0);
  domain.set_motion(m0);
  domain.restart_flow();
  walls.apply(domain, 0.0, p0);
  EXPECT_GT(domain.wall_cells(), 0u);
  for (int s = 1; s <= steps; ++s) {
    domain.step(1);
    auto [p, m] = motion_at(s * dt);
    domain.set_motion(m);
    walls.apply(domain, s * dt, p);
  }
  *voxelisations = walls.voxelisations();
  // every fluid cell: the still air seen from the grid, -(R^T v) - omega x r
  const auto [p, m] = motion_at(steps * dt);
  const auto f = domain.solver().fields();
  const auto& lat = domain.solver().lattice();
  const double to_phys = domain.units().dx() / domain.units().dt();
  const int n = domain.cells_per_edge();
  double worst = 0;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const std::size_t c = lat.index(i, j, k);
        if (lbm::is_wall(static_cast<lbm::CellType>(lat.types()[c] & ~lbm::kGeneralBit))) continue;
        const Vector3d expect = m.air_velocity - omega.cross(domain.position(i, j, k));
        const Vector3d u(f.u[3 * c] * to_phys, f.u[3 * c + 1] * to_phys, f.u[3 * c + 2] * to_phys);
        worst = std::max(worst, (u - expect).norm());
      }
  return worst;
}

// The stream stays uniform to 0.5 % of the domain's speed (uniform-stream bound), through more than
// ten re-voxelisations.
void expect_uniform(double height, const Vector3d& v, const Vector3d& omega, int nodes = 16) {
  std::size_t vox = 0;
  const double worst = disturbance(height, v, omega, 25 * nodes, &vox, nodes);  // the same 11 m of travel
  EXPECT_GT(vox, 10u);
  EXPECT_LT(worst, 0.005 * v.norm()) << "hub " << height << " m above the deck: largest deviation " << worst << " m/s";
}
}  // namespace

// The hull in the domain's lower half; the stern enters through the back face (impedance outlet) as the
// domain flies aft and sinks: 400 steps, 11 m of travel.
TEST(ShipInDomain, ShipAtRestInTheAirLeavesAUniformStreamUniformAsItCrossesTheGrid) {
  expect_uniform(3.5, Vector3d(-4.0, 0.0, 0.3), Vector3d::Zero());
}

// The approach's geometry (thesis 9.1): hub 9.5 m above the deck, the hull reaching through the
// bottom, back and side faces, kept out of their two outermost layers (thesis 6.4); the domain moves
// aft and sideways and turns.
TEST(ShipInDomain, UniformStreamStaysUniformWhileTheHullCrossesTheFacesAndTheDomainTurns) {
  expect_uniform(9.5, Vector3d(-4.0, 1.0, 0.0), Vector3d(0, 0, 0.03));
}

// The hull fills the domain's lower half (hub 3.5 m above the deck) and crosses the bottom, front,
// back and side faces while the domain moves aft and sideways. In the two outermost layers, kept
// clear of walls, the air inside the hull is held to the hull's motion (lbm::Lattice::set_held):
// left free, that dead end between hull and faces grew a jet and diverged (25.7 m/s after 800 steps
// at N = 32). N = 32: at N = 16 the gap is a single cell layer on a 1.5 m grid.
TEST(ShipInDomain, UniformStreamStaysUniformWithTheHullFillingTheLowerHalf) {
  expect_uniform(3.5, Vector3d(-4.0, 1.0, 0.0), Vector3d::Zero(), 32);
}

// KNOWN DEFECT (docs/benchmarks.md at 193c1b4, "Approach"): the same while the domain also turns (0.03 rad/s):
// 0.060 m/s at N = 16 and 0.032 m/s at N = 32 (1.5 % and 0.8 % of 4.1 m/s), no longer in the gap but
// in the fluid at the stern's corner, whose staircase changes as the grid turns past it; the error
// halves with the cell size (first order) but is above the uniform-stream bound's 0.5 % at these resolutions.
TEST(ShipInDomain, DISABLED_UniformStreamStaysUniformWithTheHullFillingTheLowerHalfWhileTheDomainTurns) {
  expect_uniform(3.5, Vector3d(-4.0, 1.0, 0.0), Vector3d(0, 0, 0.03));
}

// With the rotor's far field (LrmConfig::rotor_far_field) the ground its wake is mirrored in is the
// first surface straight below the hub along the shaft: the deck over the landing spot, the sea
// behind the ship, at (waterline - hub z) / cos(theta) along a shaft tilted by theta.
TEST(ShipInDomain, TheFarFieldsGroundIsTheDeckOrTheSeaBelowTheHub) {
  lrm::LrmConfig cfg;
  cfg.nodes = 16;
  cfg.backend = lbm::Backend::Cpu;
  cfg.rotor_far_field = true;
  lrm::LrmDomain domain(cfg);
  std::shared_ptr<const wake::ShipGeometry> ship = wake::make_natogd(1.0);
  lrm::ShipInDomain walls(ship, std::make_shared<wake::StaticMotion>());
  EXPECT_TRUE(std::isinf(walls.far_field_ground()));
  lrm::DomainPose p;
  p.hub = Vector3d(-12.75, 0, -9.5);  // 9.5 m above the deck over the landing spot
  walls.apply(domain, 0.0, p);
  EXPECT_NEAR(walls.far_field_ground(), 9.5, 0.01 * domain.units().dx());
  const double theta = 10.0 * M_PI / 180.0;
  p.hub = Vector3d(-150.0, 0, -9.5);  // far behind the stern
  p.rotation = Eigen::AngleAxisd(theta, Vector3d::UnitY()).toRotationMatrix();
  walls.apply(domain, 0.0, p);
  EXPECT_NEAR(walls.far_field_ground(), (ship->datum().waterline + 9.5) / std::cos(theta), 0.01 * domain.units().dx());
  // the domain takes it: its far field is no longer the one without ground
  rotor::RotorForceHarmonics h;
  h.cos[0] = Vector3d(0, 0, -24525);
  domain.set_stream(Vector3d(-20, 0, 0));
  domain.set_rotor_forces(h);
  lrm::LrmDomain free_air(cfg);
  free_air.set_stream(Vector3d(-20, 0, 0));
  free_air.set_rotor_forces(h);
  ASSERT_EQ(domain.far_field().size(), free_air.far_field().size());
  double difference = 0;
  for (std::size_t k = 0; k < domain.far_field().size(); ++k)
    difference = std::max(difference, (domain.far_field()[k] - free_air.far_field()[k]).norm());
  EXPECT_GT(difference, 0.01);
}
