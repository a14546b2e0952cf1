// Real-time LRM inflow with firm deadlines and Pitt-Peters fallback (see realtime_inflow.hpp).
#include "ship_lrm/lrm/realtime_inflow.hpp"

#include <algorithm>
#include <stdexcept>

namespace ship_lrm::lrm {

RealTimeInflow::RealTimeInflow(std::unique_ptr<rotor::InflowModel> slow, double interval, double budget, RealTimeMode mode)
    : slow_(std::move(slow)), interval_(interval), mode_(mode), budget_(budget) {
  if (!slow_) throw ConfigError("real-time inflow: no model to run");
  if (!(budget > 0)) throw ConfigError("real-time inflow: the deadline budget must be > 0 s");
  if (!(interval > 0)) throw ConfigError("real-time inflow: the slow model's interval must be > 0 s");
  thread_ = std::thread([this] { worker(); });
}

std::unique_ptr<RealTimeInflow> make_realtime_lrm(const LrmConfig& cfg, double warm_up, double budget, RealTimeMode mode) {
  auto lrm = std::make_unique<LrmInflow>(cfg, warm_up);
  lrm->set_catch_up_limit(kRealTimeCatchUpSteps);
  const double interval = lrm->domain().time_step();
  return std::make_unique<RealTimeInflow>(std::move(lrm), interval, budget, mode);
}

RealTimeInflow::~RealTimeInflow() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  job_ready_.notify_all();
  thread_.join();
}

void RealTimeInflow::worker() {
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    job_ready_.wait(lock, [this] { return stop_ || has_job_; });
    if (stop_) return;
    const rotor::RotorDiskState state = job_state_;
    const double dt = job_dt_;
    const long id = job_id_;
    has_job_ = false;
    busy_ = true;
    lock.unlock();
    rotor::RotorInflow out;
    std::exception_ptr err;
    try {
      slow_->advance(state, dt);
      out = slow_->inflow();
    } catch (...) {
      err = std::current_exception();
    }
    const auto finished = std::chrono::steady_clock::now();
    lock.lock();
    busy_ = false;
    ++stats_.lrm_jobs;
    result_ = out;
    result_id_ = id;
    result_time_ = finished;
    if (err) error_ = err;
    result_ready_.notify_all();
  }
}

RealTimeStats RealTimeInflow::stats() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return stats_;
}

void RealTimeInflow::wait_idle(std::unique_lock<std::mutex>& lock) {
  result_ready_.wait(lock, [this] { return !busy_ && !has_job_; });
}

void RealTimeInflow::wait_idle() {
  std::unique_lock<std::mutex> lock(mutex_);
  wait_idle(lock);
}

void RealTimeInflow::reset(const rotor::RotorDiskState& state) {
  std::unique_lock<std::mutex> lock(mutex_);
  wait_idle(lock);
  slow_->reset(state);
  fallback_.reset(state);
  served_ = slow_->inflow();
  last_lrm_ = served_;
  have_lrm_ = true;
  jobs_.clear();
  next_post_ = 0;
  pending_dt_ = 0;
}

void RealTimeInflow::advance(const rotor::RotorDiskState& state, double dt) {
  fallback_.advance(state, dt);  // always current, whatever the LRM thread does
  std::unique_lock<std::mutex> lock(mutex_);
  ++stats_.steps;
  if (error_) std::rethrow_exception(error_);
  pending_dt_ += dt;
  if (mode_ == RealTimeMode::LockStep)
    advance_lockstep(lock, state);
  else
    advance_pipelined(lock, state, dt);
}

long RealTimeInflow::post(const rotor::RotorDiskState& state) {
  const long id = ++job_id_;
  job_state_ = state;
  job_dt_ = pending_dt_;
  pending_dt_ = 0;
  has_job_ = true;
  job_ready_.notify_one();
  return id;
}

bool RealTimeInflow::collect(std::unique_lock<std::mutex>& lock, long id, std::chrono::steady_clock::time_point deadline) {
  result_ready_.wait_until(lock, deadline, [&] { return result_id_ == id || error_ != nullptr; });
  if (error_) std::rethrow_exception(error_);
  // Judged by when the LRM thread finished, not by when this thread woke up: a waiter woken late by
  // the scheduler must not accept a result that came after its deadline (firm deadline).
  return result_id_ == id && result_time_ <= deadline;
}

std::chrono::steady_clock::time_point RealTimeInflow::deadline_after(std::chrono::steady_clock::time_point posted, int steps) const {
  if (deadline_ != std::chrono::steady_clock::time_point{}) return deadline_;  // paced: this step's due time
  return posted + std::chrono::duration_cast<std::chrono::steady_clock::duration>(budget_ * steps);
}

void RealTimeInflow::advance_lockstep(std::unique_lock<std::mutex>& lock, const rotor::RotorDiskState& state) {
  if (busy_ || has_job_) {  // still working on an earlier step: this one cannot make it
    ++stats_.deadline_misses;
    stats_.last_was_fallback = true;
    served_ = fallback_.inflow();
    return;
  }
  const auto posted = std::chrono::steady_clock::now();
  const long id = post(state);
  if (collect(lock, id, deadline_after(posted, 1))) {
    served_ = result_;
    stats_.last_was_fallback = false;
    stats_.worst_wait_s = std::max(stats_.worst_wait_s, std::chrono::duration<double>(std::chrono::steady_clock::now() - posted).count());
  } else {
    ++stats_.deadline_misses;  // the result for this step will be dropped when it arrives
    stats_.last_was_fallback = true;
    served_ = fallback_.inflow();
  }
}

void RealTimeInflow::advance_pipelined(std::unique_lock<std::mutex>& lock, const rotor::RotorDiskState& state, double dt) {
  post_every_ = std::max(1, static_cast<int>(std::lround(interval_ / dt)));
  lag_steps_ = kPipelineDepth * post_every_;
  // A job the LRM thread has finished keeps its result here: the thread's one result slot is
  // reused by the next job before this one is due.
  if (!jobs_.empty() && !jobs_.back().finished && result_id_ == jobs_.back().id) {
    jobs_.back().finished = true;
    jobs_.back().result = result_;
    jobs_.back().result_time = result_time_;
  }
  // Serve the jobs that are due, oldest first: on time, the newest of them serves from now on.
  while (!jobs_.empty() && jobs_.front().due_step <= stats_.steps) {
    Job& j = jobs_.front();
    const auto t = std::chrono::steady_clock::now();
    const auto deadline = deadline_after(j.posted, lag_steps_);
    const bool on_time = j.finished ? j.result_time <= deadline : collect(lock, j.id, deadline);
    if (on_time) {
      last_lrm_ = j.finished ? j.result : result_;
      stats_.worst_wait_s = std::max(stats_.worst_wait_s, std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count());
    }
    have_lrm_ = on_time;
    jobs_.pop_front();
  }
  // Post every post_every_ steps (about one LBM step of flight time); a busy LRM thread defers it.
  if (stats_.steps >= next_post_ && !busy_ && !has_job_) {
    Job j;
    j.posted = std::chrono::steady_clock::now();
    j.id = post(state);
    j.due_step = stats_.steps + lag_steps_;
    jobs_.push_back(j);
    next_post_ = stats_.steps + post_every_;
  }
  stats_.last_was_fallback = !have_lrm_;
  if (have_lrm_) {
    served_ = last_lrm_;
  } else {
    ++stats_.deadline_misses;
    served_ = fallback_.inflow();
  }
}

}  // namespace ship_lrm::lrm
