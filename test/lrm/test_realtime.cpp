// Real-time mode of the LRM inflow ("firm deadlines"): an inflow that misses its deadline is
// replaced by Pitt-Peters for that step and counted, never served late; one that makes it is exactly
// the simulated-time (synchronous) result.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "lrm_test_config.hpp"
#include "ship_lrm/lrm/deadline_watch.hpp"
#include "ship_lrm/lrm/realtime_inflow.hpp"

using namespace ship_lrm;
using ship_lrm::Vec3;

namespace {

lrm::LrmConfig tiny_config() { return lrm::test::quick_config(16, 1.0); }

rotor::RotorDiskState state_at(int k, double dt) { return lrm::test::disk_state_at(k, dt); }

}  // namespace

TEST(RealTimeInflow, ResultsThatMakeTheirDeadlineAreTheSynchronousOnes) {
  const double dt = 0.0072;  // about one LBM step at N = 16 (7.2 ms) per coupling step
  lrm::LrmInflow sync(tiny_config(), 0.2);
  auto rt_ptr = lrm::make_realtime_lrm(tiny_config(), 0.2, 30.0);
  lrm::RealTimeInflow& rt = *rt_ptr;  // 30 s: no deadline can pass
  sync.reset(state_at(0, dt));
  rt.reset(state_at(0, dt));
  for (int k = 1; k <= 40; ++k) {
    sync.advance(state_at(k, dt), dt);
    rt.advance(state_at(k, dt), dt);
    ASSERT_EQ(rt.inflow().mean, sync.inflow().mean) << "step " << k;
    ASSERT_EQ(rt.inflow().cosine, sync.inflow().cosine) << "step " << k;
  }
  const auto st = rt.stats();
  EXPECT_EQ(st.steps, 40);
  EXPECT_EQ(st.deadline_misses, 0);
  EXPECT_FALSE(st.last_was_fallback);
}

namespace {

// Drives a real-time inflow whose budget no LRM job can meet: after the steps that have no job due
// (pipelined: the lag; lock-step: none), which serve the warm-up's LRM inflow, every step must be
// Pitt-Peters', current at every step, and counted as a miss.
void check_late_jobs_fall_back(lrm::RealTimeMode mode, double dt) {
  rotor::PittPetersInflow pp;
  auto rt_ptr = lrm::make_realtime_lrm(tiny_config(), 0.2, 1e-9, mode);
  lrm::RealTimeInflow& rt = *rt_ptr;  // no LRM job fits into a nanosecond
  pp.reset(state_at(0, dt));
  rt.reset(state_at(0, dt));
  const Vec3 lrm_start = rt.inflow().mean;
  int held = 0;
  for (int k = 1; k <= 40; ++k) {
    pp.advance(state_at(k, dt), dt);
    rt.advance(state_at(k, dt), dt);
    held = mode == lrm::RealTimeMode::Pipelined ? rt.lag_steps() : 0;
    if (k <= held)
      ASSERT_EQ(rt.inflow().mean, lrm_start) << "before the first job is due: the last on-time LRM inflow";
    else
      ASSERT_EQ(rt.inflow().mean, pp.inflow().mean) << "step " << k;
  }
  EXPECT_EQ(rt.stats().deadline_misses, 40 - held);
  EXPECT_TRUE(rt.stats().last_was_fallback);
  EXPECT_NE(rt.inflow().mean, lrm_start);
}

}  // namespace

TEST(RealTimeInflow, LateResultsAreDroppedAndPittPetersServesThoseSteps) { check_late_jobs_fall_back(lrm::RealTimeMode::LockStep, 0.0072); }

// Pipelined: a job is posted every post_every() steps (one LBM step of flight time: that step's
// loads, the time since the previous job) and due lag_steps() = kPipelineDepth * post_every() steps
// later; the inflow served at each step is the synchronous model's answer to the newest job due,
// held until the next one is due. (The test waits for the LRM thread before each step, so that no
// post is deferred and the sequence is the synchronous one.)
TEST(RealTimeInflow, PipelinedServesTheSynchronousInflowKPipelineDepthLbmIntervalsLater) {
  const double dt = 0.0036;  // half the N = 16 lattice's 7.2 ms step
  lrm::LrmInflow ref(tiny_config(), 0.2);
  auto rt_ptr = lrm::make_realtime_lrm(tiny_config(), 0.2, 30.0, lrm::RealTimeMode::Pipelined);
  lrm::RealTimeInflow& rt = *rt_ptr;
  ref.reset(state_at(0, dt));
  rt.reset(state_at(0, dt));
  rotor::RotorInflow expected = ref.inflow();
  std::vector<std::pair<int, rotor::RotorInflow>> due;  // (due step, answer), oldest first
  double pending = 0;
  int changes = 0;
  for (int k = 1; k <= 60; ++k) {
    rt.wait_idle();
    rt.advance(state_at(k, dt), dt);
    ASSERT_EQ(rt.post_every(), 2) << "an LBM step of two flight steps";
    ASSERT_EQ(rt.lag_steps(), 2 * lrm::kPipelineDepth);
    pending += dt;
    while (!due.empty() && due.front().first <= k) {
      changes += due.front().second.mean != expected.mean;
      expected = due.front().second;
      due.erase(due.begin());
    }
    if ((k - 1) % rt.post_every() == 0) {
      ref.advance(state_at(k, dt), pending);
      pending = 0;
      due.emplace_back(k + rt.lag_steps(), ref.inflow());
    }
    ASSERT_EQ(rt.inflow().mean, expected.mean) << "step " << k;
    ASSERT_EQ(rt.inflow().cosine, expected.cosine) << "step " << k;
  }
  EXPECT_GT(changes, 10) << "the LRM inflow must evolve, or the comparison shows nothing";
  EXPECT_EQ(rt.stats().deadline_misses, 0);
}

// Catch-up limit (real time): an advance that covers more LBM steps than the limit runs only the
// newest ones and moves the domain's clock on by the whole time; the next ordinary advance runs
// one step. Without a limit every step runs.
TEST(LrmInflow, CatchUpLimitRunsOnlyTheNewestStepsAndKeepsTheClock) {
  lrm::LrmInflow limited(tiny_config(), 0.2), full(tiny_config(), 0.2);
  const double dt = limited.domain().time_step();
  limited.set_catch_up_limit(2);
  limited.reset(state_at(0, dt));
  full.reset(state_at(0, dt));
  const long s0 = limited.lbm_steps(), f0 = full.lbm_steps();
  const double t0 = limited.domain().time();
  limited.advance(state_at(1, dt), 10 * dt);
  full.advance(state_at(1, dt), 10 * dt);
  EXPECT_EQ(limited.lbm_steps() - s0, 2);
  EXPECT_EQ(full.lbm_steps() - f0, 10);
  EXPECT_EQ(limited.dropped_steps(), 8);
  EXPECT_EQ(full.dropped_steps(), 0);
  EXPECT_NEAR(limited.domain().time() - t0, 10 * dt, 1e-9 * dt);
  EXPECT_EQ(limited.domain().time(), full.domain().time());
  limited.advance(state_at(2, dt), dt);
  EXPECT_EQ(limited.lbm_steps() - s0, 3);
  EXPECT_EQ(limited.dropped_steps(), 8);
  EXPECT_TRUE(std::isfinite(limited.inflow().mean.z()));
}

TEST(RealTimeInflow, PipelinedLateJobsAreDroppedAndPittPetersServesUntilOneIsOnTime) {
  check_late_jobs_fall_back(lrm::RealTimeMode::Pipelined, 0.0036);
}

TEST(RealTimeInflow, BadBudgetIsRefused) { EXPECT_THROW(lrm::make_realtime_lrm(tiny_config(), 0.2, 0.0), ship_lrm::ConfigError); }

// The watch of a paced run: windows of simulated time in which most steps flew on Pitt-Peters are
// reported with their counts, others are not (1.8 ms steps, 5 s windows: about 2 778 steps per window).
TEST(DeadlineWatch, ReportsEachWindowInWhichMostStepsMissedTheirDeadline) {
  const double dt = 0.0018;
  lrm::DeadlineWatch watch(5.0, 0.5);
  lrm::RealTimeStats totals;
  std::vector<std::string> messages;
  for (int k = 1; k <= 8334; ++k) {  // 15 s: windows 0-5 s (40 % missed), 5-10 s (90 %), 10-15 s (half, not more)
    const double t = k * dt;
    ++totals.steps;
    const int phase = static_cast<int>(k / 2778.0);  // 2778 steps = 5 s
    if ((phase == 0 && k % 5 < 2) || (phase == 1 && k % 10 != 0) || (phase == 2 && k % 2 == 0)) ++totals.deadline_misses;
    const std::string m = watch.update(t, totals);
    if (!m.empty()) messages.push_back(m);
  }
  ASSERT_EQ(messages.size(), 1u);
  EXPECT_EQ(watch.reports(), 1);
  // the second window, 5 to 10 s: 9 of 10 of its steps missed
  EXPECT_NE(messages[0].find("(90 %)"), std::string::npos) << messages[0];
  EXPECT_NE(messages[0].find("from t = 5.0 to 10.0 s"), std::string::npos) << messages[0];
  EXPECT_NE(messages[0].find("backend cuda"), std::string::npos) << messages[0];
}

TEST(DeadlineWatch, RefusesAWindowOrThresholdThatMeansNothing) {
  EXPECT_THROW(lrm::DeadlineWatch(0.0, 0.5), std::invalid_argument);
  EXPECT_THROW(lrm::DeadlineWatch(std::nan(""), 0.5), std::invalid_argument);
  EXPECT_THROW(lrm::DeadlineWatch(5.0, 1.5), std::invalid_argument);
  EXPECT_THROW(lrm::DeadlineWatch(5.0, -0.1), std::invalid_argument);
}
