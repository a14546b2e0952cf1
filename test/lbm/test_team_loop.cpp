// TeamLoop (team_loop.hpp): the CPU backend's work sharing, and that the CPU solver's result does not
// depend on how many threads share a step.
#include <gtest/gtest.h>
#include <omp.h>

#include <atomic>
#include <chrono>
#include <thread>
#include <vector>

#include "flow_cases.hpp"
#include "ship_lrm/lbm/solver.hpp"
#include "ship_lrm/lbm/team_loop.hpp"

namespace ship_lrm::lbm {
namespace {

// Runs a TeamLoop over n iterations (shares for `shares` threads, chunk `chunk`) with a team of
// `team` threads; returns how often each iteration ran.
std::vector<int> run_counts(long n, int shares, long chunk, int team) {
  TeamLoop loop;
  loop.reset(n, shares, chunk);
  std::vector<std::atomic<int>> count(static_cast<std::size_t>(n));
#pragma omp parallel num_threads(team)
  loop.run(omp_get_thread_num(), [&](long i) { count[i].fetch_add(1); });
  std::vector<int> out;
  for (auto& c : count) out.push_back(c.load());
  return out;
}

// Every iteration runs exactly once, for teams equal to, larger and smaller than the shares, any
// chunk (1, one that does not divide the shares, one larger than the loop) and loops shorter than
// the team; and again after a reset to another length (the loop is reused every step).
TEST(TeamLoop, EveryIterationRunsOnceWhateverTheTeam) {
  omp_set_dynamic(0);
  for (long n : {0L, 1L, 3L, 1000L, 1613L})
    for (int shares : {1, 2, 3})
      for (int team : {1, 2, 3, 4})
        for (long chunk : {1L, 7L, 5000L}) {
          const std::vector<int> c = run_counts(n, shares, chunk, team);
          for (long i = 0; i < n; ++i)
            ASSERT_EQ(c[i], 1) << "n " << n << " shares " << shares << " team " << team << " chunk " << chunk << " iteration " << i;
        }
  TeamLoop loop;
  for (long n : {500L, 20L, 900L}) {
    loop.reset(n, 2, 16);
    std::vector<std::atomic<int>> count(static_cast<std::size_t>(n));
#pragma omp parallel num_threads(2)
    loop.run(omp_get_thread_num(), [&](long i) { count[i].fetch_add(1); });
    for (long i = 0; i < n; ++i) ASSERT_EQ(count[i].load(), 1) << "after a reset to " << n;
  }
}

// A thread held up (here: asleep before it starts, as a thread descheduled by the flight model's
// or woken late) does not hold up its share: the other thread takes it over.
TEST(TeamLoop, AThreadHeldUpHasItsShareTakenOver) {
  omp_set_dynamic(0);
  const long n = 4000;
  TeamLoop loop;
  loop.reset(n, 2, 8);
  std::atomic<long> by_thread[2] = {{0}, {0}};
  std::atomic<bool> done{false};
#pragma omp parallel num_threads(2)
  {
    const int t = omp_get_thread_num();
    if (t == 0)  // held up until the other thread has finished, at most 10 s
      for (int k = 0; k < 1000 && !done.load(); ++k) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    loop.run(t, [&](long) { by_thread[t].fetch_add(1); });
    if (t == 1) done.store(true);
  }
  if (omp_get_max_threads() < 2 && by_thread[1].load() == 0) GTEST_SKIP() << "no second OpenMP thread";
  EXPECT_EQ(by_thread[0].load() + by_thread[1].load(), n);
  EXPECT_EQ(by_thread[1].load(), n) << "the held-up thread's share was not taken over";
}

// The CPU solver's populations after `steps` steps with `threads` OpenMP threads, on a lattice with
// every kind of cell a step visits: bulk segments, cells next to resting walls (segments with link
// masks), cells next to a moving wall (general cells), held cells, a force field and, with `open`,
// a velocity inlet, an impedance and a pressure outlet (the boundary passes); without, the held
// cells follow the fluid cells' pass directly.
std::vector<float> populations_with_threads(bool open, int threads, long steps) {
  LatticeConfig cfg = test::periodic_config(24, 14, 12, 0.02f);
  cfg.collision.smagorinsky = 0.1f;
  cfg.faces[4].type = cfg.faces[5].type = FaceType::Wall;
  if (open) {
    cfg.faces[0].type = FaceType::VelocityInlet;
    cfg.faces[0].velocity = {0.05f, 0.01f, 0.0f};
    cfg.faces[1].type = FaceType::ImpedanceOutlet;
    cfg.faces[4].type = FaceType::PressureOutlet;
    cfg.faces[4].density = 1.0f;
  }
  Lattice lat(cfg);
  for (int x = 6; x < 9; ++x)
    for (int y = 4; y < 9; ++y) lat.set_wall(x, y, 5);  // a resting block
  WallMotion spin;
  spin.omega[2] = 0.004f;
  spin.centre[0] = 15.5f, spin.centre[1] = 6.5f, spin.centre[2] = 6.5f;
  const int w = lat.add_wall_motion(spin);
  for (int z = 5; z < 8; ++z)
    for (int y = 5; y < 8; ++y)
      for (int x = 14; x < 17; ++x) lat.set_moving_wall(x, y, z, w);
  // held cells in every row of a plane (next to the inlet when open): some lie in each thread's last chunk
  for (int z = 1; z < cfg.nz - 1; ++z)
    for (int y = 0; y < cfg.ny; ++y) lat.set_held(1, y, z, w);
  const int was = omp_get_max_threads();
  omp_set_num_threads(threads);
  auto s = make_cpu_solver(std::move(lat));
  std::vector<float> force(3 * s->lattice().cells(), 0.0f);
  for (std::size_t c = 0; c < force.size() / 3; c += 7) force[3 * c + 2] = 1e-5f;
  s->set_force_field(force);
  s->step(steps);
  omp_set_num_threads(was);
  return s->populations();
}

// The same populations, bit for bit, with 1, 2 and 3 threads. Each cell's update depends on nothing
// but its own and its neighbours' slots (A-A pattern), so the order in which the threads take the
// cells must not matter; a pass begun before the one it reads from has ended would show up here.
TEST(CpuSolver, SameResultWithAnyNumberOfThreads) {
  for (bool open : {true, false}) {
    const std::vector<float> reference = populations_with_threads(open, 1, 41);  // ends after an odd step
    for (int threads : {2, 3}) {
      const std::vector<float> g = populations_with_threads(open, threads, 41);
      for (std::size_t k = 0; k < g.size(); ++k)
        ASSERT_EQ(g[k], reference[k]) << (open ? "open faces, " : "closed, ") << threads << " threads, population slot " << k;
    }
  }
}

}  // namespace
}  // namespace ship_lrm::lbm
