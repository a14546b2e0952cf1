// The rigid body conserves angular momentum and energy when torque-free, and
// falls at exactly g with the aerodynamics off.
#include <gtest/gtest.h>

#include "ship_lrm/flight/helicopter.hpp"

using namespace ship_lrm::flight;
using ship_lrm::Vec3;

TEST(RigidBody, TorqueFreeTumblingConservesMomentumAndEnergy) {
  const auto p = load_default_bo105();
  Eigen::Matrix3d inertia;
  inertia << p.mass.ixx, 0, -p.mass.ixz, 0, p.mass.iyy, 0, -p.mass.ixz, 0, p.mass.izz;
  const RigidBody body(p.mass.mass, inertia);
  RigidBodyState s;
  s.rate = Vec3(0.4, 1.5, -0.3);  // tumbling about all three axes, mostly the intermediate one
  s.velocity = Vec3(3, -1, 2);
  const Vec3 h0 = body.angular_momentum_world(s);
  const double e0 = body.kinetic_energy(s);
  const double dt = p.time_step;
  const auto no_loads = [](const RigidBodyState&) { return Wrench{}; };
  double max_dh = 0, max_de = 0;
  for (int i = 0; i < static_cast<int>(10.0 / dt); ++i) {
    s = body.step(s, dt, no_loads);
    max_dh = std::max(max_dh, (body.angular_momentum_world(s) - h0).norm() / h0.norm());
    max_de = std::max(max_de, std::abs(body.kinetic_energy(s) - e0) / e0);
  }
  EXPECT_LT(max_dh, 1e-6);
  EXPECT_LT(max_de, 1e-6);
  EXPECT_GT((s.rate - Vec3(0.4, 1.5, -0.3)).norm(), 0.1) << "the body must actually tumble";
}

TEST(RigidBody, FreeFallWithoutAerodynamicsIsExactlyG) {
  const auto p = load_default_bo105();
  Helicopter heli(p, nullptr, EngineMode::ConstantSpeed);
  heli.set_aerodynamics(false);
  heli.reset(RigidBodyState{});
  const int steps = static_cast<int>(1.0 / p.time_step);
  for (int i = 0; i < steps; ++i) heli.step();
  const double t = heli.time();
  const auto& b = heli.body();
  const double g = p.mass.gravity;
  EXPECT_NEAR(heli.outputs().acceleration.z(), g, 1e-9 * g);
  EXPECT_NEAR(b.position.z(), 0.5 * g * t * t, 1e-9 * 0.5 * g * t * t);
  EXPECT_NEAR((b.attitude * b.velocity).z(), g * t, 1e-9 * g * t);
  EXPECT_LT(b.rate.norm(), 1e-9);
  EXPECT_LT(std::hypot(b.position.x(), b.position.y()), 1e-9);
}
