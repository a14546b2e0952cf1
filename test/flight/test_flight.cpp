// Flight-model validation: hover (1), trim sweep (2), collective step (3), doublets (5), bad input (7).
#include <gtest/gtest.h>

#include <cmath>
#include <utility>
#include <vector>

#include "ship_lrm/flight/doublet.hpp"
#include "ship_lrm/flight/trim.hpp"
#include "ship_lrm/rotor/momentum_theory.hpp"

using namespace ship_lrm::flight;
using ship_lrm::Vec3;

namespace {
constexpr double kDeg = 180.0 / M_PI;
}

TEST(Flight, HoverTrimBalancesWeightAndMatchesMomentumTheory) {
  const auto p = load_default_bo105();
  Helicopter heli(p);
  const TrimResult r = trim(heli, TrimTarget{});
  ASSERT_TRUE(r.converged) << r.message;
  const double weight = p.mass.mass * p.mass.gravity;
  // Thrust (world-vertical part of the rotor's aerodynamic force) carries weight plus download.
  const Eigen::Matrix3d to_world = r.body.attitude.toRotationMatrix() * heli.mr_to_body();
  Vec3 rotor_world = Vec3::Zero();
  Vec3 inflow = Vec3::Zero();
  const int rev = static_cast<int>(std::ceil(2 * M_PI / (p.main_rotor.rotor_speed * p.time_step)));
  heli.set_body_held(true);
  double download = 0;
  for (int i = 0; i < rev; ++i) {
    heli.step();
    rotor_world += to_world * heli.outputs().rotor.aero_force / rev;
    download += heli.outputs().airframe.fuselage.force.z() / rev;
  }
  EXPECT_GT(download, 0.005 * weight) << "the fuselage in the rotor wake must see a download";
  EXPECT_NEAR(-rotor_world.z(), weight + download, 0.01 * weight);
  // Pitt-Peters hover inflow = momentum theory for this thrust within 1 %
  const double vh = ship_lrm::rotor::hover_induced_velocity(r.thrust, p.density, p.main_rotor.radius);
  EXPECT_NEAR(r.induced_velocity, vh, 0.01 * vh);
  // Power: above the ideal induced power (figure of merit < 1), below the installed 2 x 313 kW.
  const double ideal = r.thrust * vh;
  const double fm = ideal / r.main_power;
  EXPECT_GT(fm, 0.6);  // modern rotors reach 0.7-0.8 (Leishman, Principles of Helicopter Aerodynamics, ch. 2)
  EXPECT_LT(fm, 0.8);
  EXPECT_LT(r.total_power, p.engine.max_power);
  RecordProperty("hover_power_kW", std::to_string(r.total_power / 1e3));
}

TEST(Flight, TrimSweepFollowsThePowerBucketAndAttitudeTrends) {
  const auto p = load_default_bo105();
  Helicopter heli(p);
  TrimOptions opt;
  std::vector<TrimResult> res;
  std::vector<double> speeds;
  for (double v = 0; v <= 70.0 + 1e-9; v += 5) {
    TrimTarget t;
    t.speed = v;
    res.push_back(trim(heli, t, opt));
    speeds.push_back(v);
    ASSERT_TRUE(res.back().converged) << res.back().message;
    EXPECT_LT(res.back().residual, opt.tolerance);
    opt.initial_controls = res.back().controls;
    opt.initial_attitude = Vec3(res.back().roll, res.back().pitch, 0);
  }
  size_t imin = 0;
  for (size_t i = 0; i < res.size(); ++i)
    if (res[i].total_power < res[imin].total_power) imin = i;
  EXPECT_GE(speeds[imin], 20.0);
  EXPECT_LE(speeds[imin], 40.0);
  EXPECT_GT(res.front().total_power, 1.3 * res[imin].total_power);  // a pronounced bucket
  for (size_t i = 3; i < res.size(); ++i) {
    EXPECT_LT(res[i].pitch, res[i - 1].pitch) << "nose-down pitch grows with speed, at " << speeds[i];
    EXPECT_GT(res[i].controls.longitudinal, res[i - 1].controls.longitudinal) << "more forward stick at " << speeds[i];
  }
  EXPECT_LT(res.back().pitch * kDeg, -3.0);
  // collective follows the power curve (thesis 8.2.1): its minimum is in the bucket too
  size_t cmin = 0;
  for (size_t i = 0; i < res.size(); ++i)
    if (res[i].controls.collective < res[cmin].controls.collective) cmin = i;
  EXPECT_GE(speeds[cmin], 20.0);
  EXPECT_LE(speeds[cmin], 40.0);
}

TEST(Flight, CollectiveStepOvershootsThenSettlesOnMomentumTheory) {
  // Thesis 2.1: after a collective step the inflow lags, so the thrust overshoots before settling.
  const auto p = load_default_bo105();
  Helicopter heli(p, nullptr, EngineMode::ConstantSpeed);
  const TrimResult r = trim(heli, TrimTarget{});
  ASSERT_TRUE(r.converged) << r.message;
  heli.set_body_held(true);  // whirl tower: the fuselage is held, the rotor and its inflow are free
  heli.engine().set_mode(EngineMode::ConstantSpeed);
  const double dt = p.time_step;
  const int rev = static_cast<int>(std::ceil(2 * M_PI / (p.main_rotor.rotor_speed * dt)));
  const auto mean_thrust = [&](int revs, double* inflow) {
    double t = 0, v = 0;
    for (int i = 0; i < revs * rev; ++i) {
      heli.step();
      t += -heli.outputs().rotor.aero_force.z();
      v += heli.outputs().inflow.mean.z();
    }
    if (inflow) *inflow = v / (revs * rev);
    return t / (revs * rev);
  };
  const double t0 = mean_thrust(1, nullptr);
  BladeAngles a = heli.blade_angles();
  a.main.collective += 1.5 / kDeg;
  heli.set_blade_angles(a);
  double peak = 0, v_early = 0;
  // quarter-revolution averages (the 4/rev ripple averaged out) over the first 0.3 s
  const int quarter = rev / 4;
  for (int k = 0; k < static_cast<int>(0.3 / (quarter * dt)); ++k) {
    double t = 0;
    for (int i = 0; i < quarter; ++i) {
      heli.step();
      t += -heli.outputs().rotor.aero_force.z() / quarter;
      if (k == 0 && i == quarter / 2) v_early = heli.outputs().inflow.mean.z();  // 1/8 revolution after the step
    }
    peak = std::max(peak, t);
  }
  double v_final = 0;
  mean_thrust(25, nullptr);
  const double t_final = mean_thrust(2, &v_final);
  EXPECT_GT(t_final, t0 * 1.05) << "a 1.5 deg step raises the thrust";
  EXPECT_GT(peak, t_final + 0.3 * (t_final - t0)) << "overshoot: peak " << peak << " final " << t_final << " start " << t0;
  const double v0 = r.induced_velocity;
  EXPECT_LT(v_early - v0, 0.25 * (v_final - v0)) << "the inflow lags the thrust";
  const double vh = ship_lrm::rotor::hover_induced_velocity(t_final, p.density, p.main_rotor.radius);
  EXPECT_NEAR(v_final, vh, 0.01 * vh);
}

TEST(Flight, DoubletsRespondOnAxisWithTheRightSign) {
  // Thesis 8.2.2 / fig. 8.8: lateral doublet to the right at 13.37 m/s; appendix VI longitudinal and
  // collective doublets. Right stick rolls right (p > 0), forward stick pitches nose down (q < 0),
  // up collective climbs (rate of descent < 0), during the first half of each doublet.
  const auto p = load_default_bo105();
  const auto peak_first_half = [&](ControlAxis axis, int which) {
    DoubletOptions o;
    o.axis = axis;
    o.duration = 3.0;
    const DoubletResult r = run_doublet(p, o);
    double extreme = 0, sign_check = 0;
    for (const auto& s : r.samples) {
      if (s.time < o.start || s.time > o.start + o.pulse) continue;
      const double v = which < 3 ? s.rates[which] : s.rate_of_descent - r.samples.front().rate_of_descent;
      if (std::abs(v) > std::abs(extreme)) extreme = v;
      sign_check += v;
    }
    return extreme;
  };
  const double p_peak = peak_first_half(ControlAxis::Lateral, 0) * kDeg;
  const double q_peak = peak_first_half(ControlAxis::Longitudinal, 1) * kDeg;
  const double rod = peak_first_half(ControlAxis::Collective, 3);
  EXPECT_GT(p_peak, 5.0);  // deg/s; a 10 % lateral input of a hingeless rotor rolls briskly
  EXPECT_LT(p_peak, 80.0);
  EXPECT_LT(q_peak, -2.0);
  EXPECT_GT(q_peak, -60.0);
  EXPECT_LT(rod, -0.5);  // m/s climbing
  EXPECT_GT(rod, -15.0);
}

TEST(Flight, GovernedRotorSpeedDroopsInACollectiveDoublet) {
  const auto p = load_default_bo105();
  DoubletOptions o;
  o.axis = ControlAxis::Collective;
  o.amplitude = 20;
  o.duration = 4;
  const DoubletResult r = run_doublet(p, o);
  double lo = 1, hi = 1;
  for (const auto& s : r.samples) {
    lo = std::min(lo, s.rotor_speed_ratio);
    hi = std::max(hi, s.rotor_speed_ratio);
  }
  EXPECT_LT(lo, 0.995) << "the rotor speed must droop when the collective goes up";
  EXPECT_GT(lo, 0.90) << "the governor holds the droop to a few per cent (flight test: 5 +- 1 %, thesis 8.2.2)";
  EXPECT_LT(hi, 1.10);
}

TEST(Flight, FailedTrimSaysSoWithItsResidual) {
  const auto p = load_default_bo105();
  Helicopter heli(p);
  TrimTarget t;
  t.speed = 140;  // far beyond the Bo 105's envelope
  TrimOptions o;
  o.max_iterations = 8;
  const TrimResult r = trim(heli, t, o);
  EXPECT_FALSE(r.converged);
  EXPECT_NE(r.message.find("NOT converge"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("residual"), std::string::npos) << r.message;
}

TEST(Flight, TrimReportsEachNewtonIteration) {
  Helicopter heli(load_default_bo105());
  TrimTarget t;
  t.speed = 30;
  TrimOptions o;
  std::vector<std::pair<int, double>> seen;
  o.progress = [&](int iteration, double residual) { seen.emplace_back(iteration, residual); };
  const TrimResult r = trim(heli, t, o);
  ASSERT_TRUE(r.converged) << r.message;
  // one call per iteration, numbered from the starting point (0) to the converged one
  ASSERT_EQ(seen.size(), static_cast<size_t>(r.iterations) + 1);
  for (size_t k = 0; k < seen.size(); ++k) EXPECT_EQ(seen[k].first, static_cast<int>(k));
  EXPECT_DOUBLE_EQ(seen.back().second, r.residual);
  EXPECT_LT(seen.back().second, o.tolerance);
  EXPECT_GT(seen.front().second, o.tolerance) << "a cold start is not already trimmed";
}
