// A loop shared by an OpenMP team that tolerates a thread being held up: each thread owns a
// contiguous share of the iterations (as schedule(static): the same cells every step), takes it in
// chunks from its own counter, and when its share is done takes the chunks left in the others'.
//
// Why: in the real-time modes the LRM's two OpenMP threads share this project's 2-core machine with
// the flight model's thread, which wakes every flight step and takes a core from one of them. With a
// static split the other thread then waited at the next barrier for as long as the flight step ran,
// and a thread woken late at the start of a parallel region held up the step the same way.
// schedule(dynamic) takes the work over but every chunk goes through one shared counter, whose cache
// line moves between the cores at each claim: on this VM that made a real-time step 10 - 34 % slower
// than the static split. This loop made it 11 - 14 % faster, and a simulated-time step (nothing else
// running) 6 - 20 % faster, the static split's imbalance gone (docs/benchmarks.md at 193c1b4, 2026-12-02). A
// thread touches another's counter only once its own share is done.
#pragma once

#include <atomic>
#include <memory>

namespace ship_lrm::lbm {

class TeamLoop {
 public:
  // Iterations [0, n) in chunks of `chunk`, shares for `threads` threads. Call outside the parallel
  // region (or from one thread, followed by a barrier) before the team runs the loop.
  void reset(long n, int threads, long chunk) {
    if (threads < 1) threads = 1;
    if (threads != threads_) {
      cursor_ = std::make_unique<Cursor[]>(threads);
      threads_ = threads;
    }
    chunk_ = chunk < 1 ? 1 : chunk;
    for (int t = 0; t < threads_; ++t) {
      cursor_[t].next.store(n * t / threads_, std::memory_order_relaxed);
      cursor_[t].end = n * (t + 1) / threads_;
    }
  }
  // Thread t of the team runs body(i) for its share's iterations, then for what is left of the
  // others'. Every iteration runs once over the team, whatever its size (a thread beyond the shares
  // only helps; the shares of missing threads are left to the others). No barrier at the end.
  template <class Body>
  void run(int t, Body&& body) {
    for (int k = 0; k < threads_; ++k) take(cursor_[(t + k) % threads_], body);
  }

 private:
  struct alignas(64) Cursor {
    std::atomic<long> next{0};
    long end = 0;
  };
  template <class Body>
  void take(Cursor& c, Body& body) {
    for (;;) {
      const long first = c.next.fetch_add(chunk_, std::memory_order_relaxed);
      if (first >= c.end) return;
      const long last = first + chunk_ < c.end ? first + chunk_ : c.end;
      for (long i = first; i < last; ++i) body(i);
    }
  }
  std::unique_ptr<Cursor[]> cursor_;
  int threads_ = 0;
  long chunk_ = 1;
};

}  // namespace ship_lrm::lbm
