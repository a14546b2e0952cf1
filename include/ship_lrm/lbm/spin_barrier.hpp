// A barrier for the threads of one OpenMP team inside a parallel region that never puts a thread to
// sleep: a thread that arrives early spins, and after a short while yields its core between checks
// (to the flight model's thread, say, where one is waiting for it) instead of sleeping in the kernel.
//
// Why: between the LRM's real-time jobs libgomp's idle threads should sleep (a spinning OpenMP
// thread takes the core the paced flight thread needs: GOMP_SPINCOUNT=100 in the real-time
// launches, and libgomp's own throttle where it manages more threads than CPUs), but the same
// setting makes every `#pragma omp barrier` inside a step where one thread is a few microseconds
// ahead a futex sleep and wake-up, which costs tens of microseconds on this project's VM (the
// hypervisor's interrupt path). Inside a step the partner is always about to arrive, so waiting
// without sleeping is the right trade (docs/benchmarks.md, "ROS layer in real time", session 22).
//
// Sense-reversing (generation) barrier: the last thread to arrive resets the count and advances the
// generation; the others wait for the generation to change. Every write a thread made before wait()
// is visible to every thread of the team after it (acquire/release through the two atomics).
#pragma once

#include <atomic>
#include <thread>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace ship_lrm::lbm {

class SpinBarrier {
 public:
  // Called by each of the `team` threads (the same number from all of them, e.g. omp_get_num_threads()).
  void wait(int team) {
    if (team <= 1) return;
    const unsigned generation = generation_.load(std::memory_order_acquire);
    if (arrived_.fetch_add(1, std::memory_order_acq_rel) + 1 == team) {
      arrived_.store(0, std::memory_order_relaxed);
      generation_.store(generation + 1, std::memory_order_release);
      return;
    }
    for (long spin = 0; generation_.load(std::memory_order_acquire) == generation; ++spin) {
      if (spin < kSpinsBeforeYield)
        pause();
      else
        std::this_thread::yield();
    }
  }

 private:
  // some microseconds of pause instructions (tens of cycles each) before the first yield
  static constexpr long kSpinsBeforeYield = 1024;
  static void pause() {
#if defined(__x86_64__) || defined(__i386__)
    _mm_pause();
#endif
  }
  alignas(64) std::atomic<int> arrived_{0};
  alignas(64) std::atomic<unsigned> generation_{0};
};

}  // namespace ship_lrm::lbm
