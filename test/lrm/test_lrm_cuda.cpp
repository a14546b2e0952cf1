// The LRM domain on the CUDA backend against the CPU backend: the same lattice (velocity
// faces front and sides, impedance faces back, top and bottom; no bodies), the same frame motion,
// rotor forces and inflow read-out. The backends share every per-cell function
// and are compiled without contraction, so the fields must agree to rounding after one step and
// stay bit-identical in practice (docs/benchmarks.md at 193c1b4). Runs where a CUDA device exists
// (scripts/gpu_check.sh), reports itself skipped elsewhere.
#include <gtest/gtest.h>

#include <cstdio>

#include "../lbm/backend_difference.hpp"
#include "lrm_test_config.hpp"
#include "ship_lrm/lbm/solver.hpp"

using namespace ship_lrm;

namespace {

void compare(lrm::LrmDomain& cpu, lrm::LrmDomain& gpu, long steps, double tolerance, const char* what) {
  cpu.step(steps);
  gpu.step(steps);
  const auto d = lbm::test::backend_difference(cpu.solver().lattice(), cpu.solver().fields(), gpu.solver().fields());
  std::printf("%s, after %ld steps: %s\n", what, cpu.solver().steps_done(), d.text.c_str());
  EXPECT_LT(d.du, tolerance) << what;
  EXPECT_LT(d.drho, tolerance) << what;
}

}  // namespace

TEST(CudaLrmDomain, MatchesCpuInATurningStreamWithRotorForces) {
  if (!lbm::cuda_available()) GTEST_SKIP() << "no CUDA device: run scripts/gpu_check.sh on a GPU machine";
  lrm::LrmConfig cfg = lrm::test::quick_config(16);
  lrm::LrmDomain cpu(cfg);
  cfg.backend = lbm::Backend::Cuda;
  lrm::LrmDomain gpu(cfg);
  ASSERT_STREQ(gpu.solver().backend_name(), "cuda");
  lrm::LrmDomain::Motion m;
  m.air_velocity = ship_lrm::Vec3(-12.0, 2.0, 1.0);
  m.omega = ship_lrm::Vec3(0.02, -0.05, 0.1);
  for (lrm::LrmDomain* d : {&cpu, &gpu}) {
    d->set_motion(m);
    d->restart_flow();
  }
  EXPECT_EQ(cpu.solver().boundary_values(), gpu.solver().boundary_values());
  compare(cpu, gpu, 1, 1e-6, "stream");
  compare(cpu, gpu, 1, 1e-6, "stream");
  compare(cpu, gpu, 20, 1e-5, "stream");
  rotor::RotorForceHarmonics h;
  h.cos[0] = ship_lrm::Vec3(300.0, 0.0, -24525.0);
  h.cos[1] = ship_lrm::Vec3(0.0, 0.0, 1500.0);
  h.sin[2] = ship_lrm::Vec3(0.0, 0.0, -800.0);
  for (lrm::LrmDomain* d : {&cpu, &gpu}) d->set_rotor_forces(h);
  compare(cpu, gpu, 1, 1e-6, "rotor forces");
  compare(cpu, gpu, 20, 1e-5, "rotor forces");
  m.omega = ship_lrm::Vec3(0.03, -0.04, 0.12);  // a manoeuvre: new face values and fictitious forces
  m.omega_dot = ship_lrm::Vec3(0.5, 0.0, -0.2);
  m.hub_acceleration = ship_lrm::Vec3(1.0, 0.0, 0.3);
  for (lrm::LrmDomain* d : {&cpu, &gpu}) d->set_motion(m);
  compare(cpu, gpu, 1, 1e-6, "manoeuvre");
  compare(cpu, gpu, 20, 1e-5, "manoeuvre");
  const rotor::RotorInflow a = cpu.inflow(), b = gpu.inflow();
  EXPECT_LT((a.mean - b.mean).norm(), 1e-5 * a.mean.norm());
  EXPECT_LT((a.sine - b.sine).norm() + (a.cosine - b.cosine).norm(), 1e-5 * a.mean.norm());
}

// The same lattice on bare solvers, started in the domain's rotating air with the frame's forces on:
// the first step on each backend (2026-12-04: on an H200 the LRM domain's backends parted after one
// step at the back face's impedance cells in a turning domain, while the same per-cell functions run
// on the host in the CUDA backend's order agree with the CPU backend bit for bit; this case tells
// whether the device parts from the host in the solver itself or in how the domain drives it).
TEST(CudaLrmDomain, LatticeOfATurningDomainMatchesCpuOnBareSolvers) {
  if (!lbm::cuda_available()) GTEST_SKIP() << "no CUDA device: run scripts/gpu_check.sh on a GPU machine";
  lrm::LrmDomain dom(lrm::test::quick_config(16));
  lrm::LrmDomain::Motion m;
  m.omega = ship_lrm::Vec3(0, 0, 0.1);
  dom.set_motion(m);
  dom.restart_flow();
  const lbm::Lattice lat = dom.solver().lattice();
  const std::vector<float> values = dom.solver().boundary_values();
  const lbm::Fields start = dom.solver().fields();
  for (const bool frame : {false, true}) {
    auto cpu = lbm::make_cpu_solver(lat);
    auto gpu = lbm::make_cuda_solver(lat);
    lbm::FrameMotion f;
    f.omega = {0.0f, 0.0f, static_cast<float>(0.1 * dom.time_step())};
    const float centre = static_cast<float>(dom.centre());
    f.centre = {centre, centre, centre};
    for (lbm::Solver* s : {cpu.get(), gpu.get()}) {
      s->set_boundary_values(values);
      if (frame) s->set_frame_motion(f);
      s->initialize(std::vector<float>(lat.cells(), 1.0f), start.u);
    }
    for (int step = 1; step <= 2; ++step) {
      cpu->step(1);
      gpu->step(1);
      const lbm::Fields a = cpu->fields(), b = gpu->fields();
      const auto d = lbm::test::backend_difference(lat, a, b);
      const std::size_t c = lat.index(0, 5, 5);
      std::printf("frame %d, step %d: %s; back-face cell (0, 5, 5): u_y %.9g (cpu) %.9g (cuda)\n", frame, step, d.text.c_str(),
                  a.u[3 * c + 1], b.u[3 * c + 1]);
      EXPECT_LT(d.du, 1e-6) << "frame " << frame << ", step " << step;
      EXPECT_LT(d.drho, 1e-6) << "frame " << frame << ", step " << step;
    }
  }
}
