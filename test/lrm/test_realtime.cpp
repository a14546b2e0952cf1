// Real-time mode of the LRM inflow (issue 4, "firm deadlines"): an inflow that misses its deadline is
// replaced by Pitt-Peters for that step and counted, never served late; one that makes it is exactly
// the simulated-time (synchronous) result.
#include <gtest/gtest.h>

#include "lrm_test_config.hpp"
#include "ship_lrm/lrm/realtime_inflow.hpp"

using namespace ship_lrm;
using rotor::Vec3;

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

// Pipelined: the inflow served at each step is the synchronous model's answer to the job posted
// lag_steps() earlier (that step's loads, the time since the previous job), held until the next one.
TEST(RealTimeInflow, PipelinedServesTheSynchronousInflowOneLbmIntervalLater) {
  const double dt = 0.0036;  // half the N = 16 lattice's 7.2 ms step
  lrm::LrmInflow ref(tiny_config(), 0.2);
  auto rt_ptr = lrm::make_realtime_lrm(tiny_config(), 0.2, 30.0, lrm::RealTimeMode::Pipelined);
  lrm::RealTimeInflow& rt = *rt_ptr;
  ref.reset(state_at(0, dt));
  rt.reset(state_at(0, dt));
  rotor::RotorInflow expected = ref.inflow(), next;
  double pending = 0;
  long due = -1;
  int changes = 0;
  for (int k = 1; k <= 40; ++k) {
    rt.advance(state_at(k, dt), dt);
    const int m = rt.lag_steps();
    ASSERT_EQ(m, 2) << "an LBM step of two flight steps";
    pending += dt;
    if (due == k) {
      changes += next.mean != expected.mean;
      expected = next;
      due = -1;
    }
    if (due < 0) {
      ref.advance(state_at(k, dt), pending);
      pending = 0;
      next = ref.inflow();
      due = k + m;
    }
    ASSERT_EQ(rt.inflow().mean, expected.mean) << "step " << k;
    ASSERT_EQ(rt.inflow().cosine, expected.cosine) << "step " << k;
  }
  EXPECT_GT(changes, 10) << "the LRM inflow must evolve, or the comparison shows nothing";
  EXPECT_EQ(rt.stats().deadline_misses, 0);
}

TEST(RealTimeInflow, PipelinedLateJobsAreDroppedAndPittPetersServesUntilOneIsOnTime) {
  check_late_jobs_fall_back(lrm::RealTimeMode::Pipelined, 0.0036);
}

TEST(RealTimeInflow, BadBudgetIsRefused) { EXPECT_THROW(lrm::make_realtime_lrm(tiny_config(), 0.2, 0.0), lbm::ConfigError); }
