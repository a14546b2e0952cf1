// Wall-clock real-time mode of the LRM inflow (docs/design.md, "Real time"): a slow inflow
// model (the LRM domain in this process, or the LRM solver behind a LinkedInflow, e.g. the ROS
// nodelet) runs in its own thread while the flight model keeps its pace. Every coupling step posts the rotor
// state to the LRM thread and waits for that step's inflow until a firm deadline. An inflow that
// comes late is dropped and counted; that step uses the Pitt-Peters inflow, which runs alongside at
// every step so that its state is always current. A late result is never served, not even one step
// later. While the LRM thread is still busy, the newest state and the time missed accumulate, and
// the next job covers them (LrmInflow advances whole LBM steps up to the flight model's time).
//
// Two modes:
// - LockStep: the inflow of a coupling step is the LRM's answer to that step's loads, waited for
//   within the step's deadline. Only works where one LBM step fits into one flight step.
// - Pipelined: the LRM runs behind by kPipelineDepth LBM intervals. Every m flight steps, m = LBM step /
//   flight step (at least 1), a job is posted (that step's loads, the domain advanced to that
//   step's time); it is due kPipelineDepth * m steps later, and its inflow serves from then on; in
//   between, the last on-time LRM inflow serves (as the synchronous model holds its inflow between
//   LBM steps). Up to kPipelineDepth jobs are under way, one of them in the LRM thread. Each job has
//   kPipelineDepth LBM intervals of wall time, so a job that must run two LBM steps (the flight steps
//   do not divide the LBM step, so every so often one does), one that places changed walls, or one
//   slowed by the machine still makes it, at the price of an inflow kPipelineDepth LBM intervals
//   older (13.2 ms at N = 32, against the rotor's inflow time constant of the order of 0.1 s; a missed
//   job's Pitt-Peters steps moved the approach's loads further from the simulated-time run than the
//   third interval's lag: docs/benchmarks.md at 193c1b4). A job late at its due step is dropped;
//   Pitt-Peters serves until the next job makes its deadline. A busy LRM thread defers the next post.
// Simulated-time runs (deterministic) use LrmInflow or LinkedInflow directly; this class is for paced runs.
#pragma once

#include <chrono>
#include <condition_variable>
#include <deque>
#include <memory>
#include <mutex>
#include <thread>

#include "ship_lrm/lrm/lrm_inflow.hpp"
#include "ship_lrm/rotor/pitt_peters.hpp"

namespace ship_lrm::lrm {

struct RealTimeStats {
  long steps = 0;            // coupling steps served
  long deadline_misses = 0;  // steps served by the Pitt-Peters fallback
  long lrm_jobs = 0;         // jobs the LRM thread finished
  double worst_wait_s = 0;   // longest wait for a result that made its deadline
  bool last_was_fallback = false;
  double miss_fraction() const { return steps > 0 ? static_cast<double>(deadline_misses) / steps : 0.0; }
};

enum class RealTimeMode { LockStep, Pipelined };

// LBM intervals a pipelined job has between posting and its due step (see above). 3 since
// 2026-12-01: with 2 the approach on 2 CPU cores missed 2 - 4 % of its deadlines, nearly all while the ship's
// wall cells changed (about 4 ms per change, on top of a 2 ms step, within 6.6 ms). 4 since
// 2026-12-02: over ROS, alternating with 3 in five back-to-back pairs, fewer misses in four and half as many
// in sum (a wall change with its flow restart still takes 3 - 4 ms, and this VM's pace varies by 2x
// from minute to minute), for an inflow 13.2 ms old at N = 32 instead of 9.9 ms, which left C_T's
// distance to the simulated-time run unchanged (docs/benchmarks.md at 193c1b4, "ROS layer in real time", 2026-12-02).
constexpr int kPipelineDepth = 4;

// LBM steps one job of a real-time LRM may run (LrmInflow::set_catch_up_limit): a job that covers more
// (the LRM had fallen behind the wall clock) drops the older part of its backlog. No more than a
// pipelined job's kPipelineDepth intervals: a longer job would miss its deadline, the next would cover
// still more, and the pipeline would stay behind (a limit of 4 while jobs were due 2 intervals after
// posting let one disturbance cost up to 90 % of a 20 s run, 2026-11-24).
constexpr long kRealTimeCatchUpSteps = kPipelineDepth;

class RealTimeInflow final : public rotor::InflowModel {
 public:
  // slow: the model run in the LRM thread (its reset and advance only ever run there or while that
  // thread is idle); interval: its own step in simulated seconds (the LBM step: sets the pipeline's
  // lag); budget: wall-clock seconds a coupling step may wait for its inflow after posting the state
  // (pipelined: m times that, counted from the posting).
  RealTimeInflow(std::unique_ptr<rotor::InflowModel> slow, double interval, double budget, RealTimeMode mode = RealTimeMode::LockStep);
  ~RealTimeInflow() override;
  std::string name() const override { return slow_->name() + "-realtime"; }
  // Synchronous: starts (or keeps) the LRM flow and its warm-up, and the Pitt-Peters fallback.
  void reset(const rotor::RotorDiskState& state) override;
  void advance(const rotor::RotorDiskState& state, double dt) override;
  rotor::RotorInflow inflow() const override { return served_; }
  bool needs_harmonics() const override { return true; }

  RealTimeStats stats() const;
  RealTimeMode mode() const { return mode_; }
  // Pipelined: flight steps between posting a job and its due step, and between two posts (known
  // after the first advance()).
  int lag_steps() const { return lag_steps_; }
  int post_every() const { return post_every_; }
  void set_budget(double seconds) { budget_ = std::chrono::duration<double>(seconds); }
  // A paced loop gives each step an absolute deadline instead (the wall-clock time the step is due);
  // a default time_point returns to the budget.
  void set_deadline(std::chrono::steady_clock::time_point t) { deadline_ = t; }
  // Blocks until the LRM thread has no job (tests: a post is then never deferred).
  void wait_idle();
  // The slow model itself; only while the LRM thread is idle (after reset, or in tests).
  rotor::InflowModel& slow() { return *slow_; }

 private:
  void worker();
  void wait_idle(std::unique_lock<std::mutex>& lock);  // with mutex_ held
  void advance_lockstep(std::unique_lock<std::mutex>& lock, const rotor::RotorDiskState& state);
  void advance_pipelined(std::unique_lock<std::mutex>& lock, const rotor::RotorDiskState& state, double dt);
  long post(const rotor::RotorDiskState& state);  // hands the state and the pending time to the LRM thread
  // Waits for job `id` until `deadline`; true when its result was finished by then.
  bool collect(std::unique_lock<std::mutex>& lock, long id, std::chrono::steady_clock::time_point deadline);
  std::chrono::steady_clock::time_point deadline_after(std::chrono::steady_clock::time_point posted, int steps) const;
  std::unique_ptr<rotor::InflowModel> slow_;
  double interval_;
  RealTimeMode mode_;
  rotor::PittPetersInflow fallback_;
  std::chrono::duration<double> budget_;
  rotor::RotorInflow served_;
  RealTimeStats stats_;

  std::chrono::steady_clock::time_point deadline_{};
  mutable std::mutex mutex_;
  std::condition_variable job_ready_, result_ready_;
  bool stop_ = false, busy_ = false, has_job_ = false;
  long job_id_ = 0, result_id_ = -1;
  rotor::RotorDiskState job_state_;
  double job_dt_ = 0;
  rotor::RotorInflow result_;
  std::chrono::steady_clock::time_point result_time_{};  // when the LRM thread finished result_
  std::exception_ptr error_;
  // time and state not yet handed to the LRM thread (it was busy)
  double pending_dt_ = 0;
  // pipelined: the jobs under way (oldest first), and the last LRM inflow that made its deadline
  struct Job {
    long id = 0, due_step = 0;
    std::chrono::steady_clock::time_point posted{};
    bool finished = false;  // result and result_time hold the LRM thread's answer
    rotor::RotorInflow result;
    std::chrono::steady_clock::time_point result_time{};
  };
  std::deque<Job> jobs_;
  int lag_steps_ = 1, post_every_ = 1;
  long next_post_ = 0;
  bool have_lrm_ = false;
  rotor::RotorInflow last_lrm_;
  std::thread thread_;
};

// The LRM domain in this process in real time (LrmInflow as the slow model, its LBM step as the interval).
std::unique_ptr<RealTimeInflow> make_realtime_lrm(const LrmConfig& cfg, double warm_up, double budget,
                                                  RealTimeMode mode = RealTimeMode::LockStep);

}  // namespace ship_lrm::lrm
