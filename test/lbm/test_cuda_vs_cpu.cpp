// 10. The CUDA backend reproduces the CPU backend (same per-cell functions): relative max
// difference below 1e-5 after 100 steps on cases that use every boundary type. After one step the
// difference must be at rounding level (1e-6): a formula that differs shows there at once, while
// float rounding (fused multiply-adds on the device) grows only slowly. Runs where a CUDA device
// exists (scripts/gpu_check.sh), reports itself skipped elsewhere.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "backend_difference.hpp"
#include "flow_cases.hpp"

using namespace ship_lrm::lbm;
using namespace ship_lrm::lbm::test;

namespace {

Lattice every_boundary_case(CollisionModel model = CollisionModel::Bgk, bool characteristic_inlet = false) {
  LatticeConfig cfg = periodic_config(40, 24, 20, 0.02f);
  cfg.collision.smagorinsky = 0.05f;
  cfg.collision.model = model;
  cfg.faces[0].type = FaceType::VelocityInlet;
  cfg.faces[0].velocity = {0.05f, 0.0f, 0.01f};
  cfg.faces[0].characteristic_inlet = characteristic_inlet;
  cfg.faces[0].absorbing_cells = 3;  // absorb_cell after each step, beside the held block at x = 1
  cfg.faces[0].absorbing_strength = 0.5f;
  cfg.faces[1].type = FaceType::PressureOutlet;
  cfg.faces[2].type = FaceType::SlipWall;
  cfg.faces[3].type = FaceType::ImpedanceOutlet;
  cfg.faces[4].type = FaceType::Wall;
  cfg.faces[5].type = FaceType::MovingWall;
  cfg.faces[5].velocity = {0.03f, 0.01f, 0.0f};
  cfg.uniform_force = {1e-6f, 0, 0};
  Lattice lat(cfg);
  for (int z = 6; z < 12; ++z)
    for (int y = 8; y < 14; ++y) lat.set_wall(14, y, z);
  for (int x = 20; x < 30; ++x)
    for (int z = 0; z < 20; ++z) lat.set_slip_wall(x, 0, z);
  WallMotion spin;
  spin.omega[1] = 0.005f;
  spin.centre[0] = 26, spin.centre[1] = 12, spin.centre[2] = 10;
  const int w = lat.add_wall_motion(spin);
  for (int x = 24; x < 28; ++x)
    for (int y = 10; y < 14; ++y) lat.set_moving_wall(x, y, 10, w);
  // held cells: a layer on the spinning plate, moving with it, and a block at rest next to the inlet
  for (int x = 24; x < 28; ++x)
    for (int y = 10; y < 14; ++y) lat.set_held(x, y, 11, w);
  for (int z = 3; z < 7; ++z)
    for (int y = 3; y < 7; ++y) lat.set_held(1, y, z, Lattice::kHeldAtRest);
  return lat;
}

// Steps both by `steps` and compares; prints the worst cell so that a boundary bug can be located.
void compare(Solver& cpu, Solver& gpu, long steps, double tolerance) {
  cpu.step(steps);
  gpu.step(steps);
  const BackendDifference d = backend_difference(cpu.lattice(), cpu.fields(), gpu.fields());
  std::printf("after %ld steps: %s\n", cpu.steps_done(), d.text.c_str());
  EXPECT_LT(d.du, tolerance);
  EXPECT_LT(d.drho, tolerance);
}

}  // namespace

TEST(CudaBackend, MatchesCpuOnEveryBoundaryType) {
  if (!cuda_available()) GTEST_SKIP() << "no CUDA device: run scripts/gpu_check.sh on a GPU machine";
  auto cpu = make_cpu_solver(every_boundary_case());
  auto gpu = make_cuda_solver(every_boundary_case());
  compare(*cpu, *gpu, 1, 1e-6);
  compare(*cpu, *gpu, 99, 1e-5);
}

TEST(CudaBackend, MatchesCpuPeriodicWithForceField) {
  if (!cuda_available()) GTEST_SKIP() << "no CUDA device: run scripts/gpu_check.sh on a GPU machine";
  Lattice lat(periodic_config(32, 24, 16, 0.01f));
  auto cpu = make_cpu_solver(lat);
  auto gpu = make_cuda_solver(lat);
  std::vector<float> rho, u;
  taylor_green_2d(cpu->lattice(), 0.05f, rho, u);
  std::vector<float> f(3 * lat.cells());
  for (std::size_t c = 0; c < lat.cells(); ++c) f[3 * c + 2] = 1e-5f * std::sin(0.1 * c);
  for (Solver* s : {cpu.get(), gpu.get()}) {
    s->initialize(rho, u);
    s->set_force_field(f);
  }
  compare(*cpu, *gpu, 1, 1e-6);
  compare(*cpu, *gpu, 99, 1e-5);
}

// A non-inertial frame (the LRM domain turning and decelerating), with and without a force field:
// the frame's modes of both backends.
TEST(CudaBackend, MatchesCpuInAnAcceleratingRotatingFrame) {
  if (!cuda_available()) GTEST_SKIP() << "no CUDA device: run scripts/gpu_check.sh on a GPU machine";
  auto cpu = make_cpu_solver(every_boundary_case());
  auto gpu = make_cuda_solver(every_boundary_case());
  FrameMotion frame;
  frame.acceleration = {-2e-5f, 1e-5f, 0.5e-5f};
  frame.omega = {0.0f, 1e-3f, 2e-3f};
  frame.omega_dot = {1e-6f, 0.0f, -1e-6f};
  frame.centre = {20.0f, 12.0f, 10.0f};
  std::vector<float> f(3 * cpu->lattice().cells(), 0.0f);
  for (std::size_t c = 0; c < cpu->lattice().cells(); c += 11) f[3 * c + 2] = -1e-5f;
  for (Solver* s : {cpu.get(), gpu.get()}) {
    s->set_frame_motion(frame);
    s->set_force_field(f);
  }
  compare(*cpu, *gpu, 1, 1e-6);
  compare(*cpu, *gpu, 49, 1e-5);
  for (Solver* s : {cpu.get(), gpu.get()}) s->set_force_field({});
  compare(*cpu, *gpu, 50, 1e-5);
}

// The same case runs on the CPU (always): it must stay finite and conserve what it should not
// lose through walls. This keeps the every-boundary set-up exercised where no GPU exists.
// The recursive regularised collision (cell_ops.hpp) and the characteristic inlet on the device.
TEST(CudaBackend, MatchesCpuWithTheRecursiveCollisionAndACharacteristicInlet) {
  if (!cuda_available()) GTEST_SKIP() << "no CUDA device: run scripts/gpu_check.sh on a GPU machine";
  auto cpu = make_cpu_solver(every_boundary_case(CollisionModel::RecursiveRegularized, true));
  auto gpu = make_cuda_solver(every_boundary_case(CollisionModel::RecursiveRegularized, true));
  compare(*cpu, *gpu, 1, 1e-6);
  compare(*cpu, *gpu, 99, 1e-5);
}

TEST(CudaBackend, EveryBoundaryCaseRunsOnCpu) {
  for (const CollisionModel model : {CollisionModel::Bgk, CollisionModel::RecursiveRegularized}) {
    auto cpu = make_cpu_solver(every_boundary_case(model, model == CollisionModel::RecursiveRegularized));
    cpu->step(400);
    cpu->check_divergence();
    const Fields f = cpu->fields();
    for (float r : f.rho) ASSERT_TRUE(std::isfinite(r));
  }
}

// The CPU's fields() reads the bulk segments through their streaming addresses, and every other
// cell one by one: the velocities must be those of the cell-by-cell read-out (velocities()), bit
// for bit, after even and odd steps and in each force mode (the field read-out needs the force for
// the Guo half-force shift, the frame's forces the cell position).
TEST(CpuFields, EqualTheCellByCellStateInEveryForceMode) {
  auto cpu = make_cpu_solver(every_boundary_case());
  const std::size_t n = cpu->lattice().cells();
  std::vector<std::uint32_t> all(n), some;
  for (std::size_t c = 0; c < n; ++c) all[c] = static_cast<std::uint32_t>(c);
  for (std::uint32_t c = 0; c < n; c += 7) some.push_back(c);
  const auto check = [&](const char* mode) {
    for (int parity = 0; parity < 2; ++parity) {
      cpu->step(1);
      const Fields f = cpu->fields();
      const std::vector<float> u = cpu->velocities(all);
      std::size_t differ = 0;
      for (std::size_t k = 0; k < u.size(); ++k) differ += std::memcmp(&u[k], &f.u[k], sizeof(float)) != 0;
      EXPECT_EQ(differ, 0u) << mode << ", after step " << cpu->steps_done();
    }
  };
  cpu->step(20);
  check("uniform force");
  cpu->set_uniform_force({0, 0, 0});
  check("no force");
  std::vector<float> forces(3 * some.size());
  for (std::size_t k = 0; k < forces.size(); ++k) forces[k] = 1e-5f * static_cast<float>(k % 5) - 2e-5f;
  cpu->set_cell_forces(some, forces);
  check("force field");
  FrameMotion frame;
  frame.acceleration = {1e-5f, -2e-5f, 0.5e-5f};
  frame.omega = {0.0f, 0.0f, 1e-3f};
  frame.omega_dot = {1e-6f, 0.0f, 0.0f};
  frame.centre = {20.0f, 12.0f, 10.0f};
  cpu->set_frame_motion(frame);
  check("frame forces with the field");
  cpu->set_force_field({});
  check("frame forces without a field");
}

// A square patch of 8 x 8 cells in one layer of a 24 x 20 x 16 lattice: listed cells like the rotor disk's.
static std::vector<std::uint32_t> disk_like_cells(const Lattice& lat) {
  std::vector<std::uint32_t> cells;
  for (int y = 6; y < 14; ++y)
    for (int x = 8; x < 16; ++x) cells.push_back(static_cast<std::uint32_t>(lat.index(x, y, 8)));
  return cells;
}

// The listed-cell exchange the LRM uses every step (rotor-disk forces in, disk velocities out) moves
// only those cells on the device; it must give what the CPU gives.
TEST(CudaBackend, ListedCellForcesAndVelocitiesMatchCpu) {
  if (!cuda_available()) GTEST_SKIP() << "no CUDA device: run scripts/gpu_check.sh on a GPU machine";
  Lattice lat(periodic_config(24, 20, 16, 0.02f));
  auto cpu = make_cpu_solver(lat);
  auto gpu = make_cuda_solver(lat);
  const std::vector<std::uint32_t> cells = disk_like_cells(lat);
  std::vector<float> f(3 * cells.size());
  for (std::size_t k = 0; k < cells.size(); ++k) f[3 * k + 2] = -2e-3f * (1.0f + 0.1f * static_cast<float>(k % 7));
  for (Solver* s : {cpu.get(), gpu.get()}) s->set_cell_forces(cells, f);
  for (int round = 0; round < 3; ++round) {
    for (Solver* s : {cpu.get(), gpu.get()}) s->step(20);
    const auto a = cpu->velocities(cells), b = gpu->velocities(cells);
    double umax = 0, du = 0;
    for (std::size_t k = 0; k < a.size(); ++k) {
      umax = std::max(umax, static_cast<double>(std::abs(a[k])));
      du = std::max(du, static_cast<double>(std::abs(a[k] - b[k])));
    }
    ASSERT_GT(umax, 0.01) << "the disk forces must drive a flow well above float rounding (1e-7)";
    EXPECT_LT(du / umax, 1e-5) << "round " << round;
    for (float& v : f) v *= 0.5f;  // a changed force on the same cells (the cached list)
    for (Solver* s : {cpu.get(), gpu.get()}) s->set_cell_forces(cells, f);
  }
}

// The rotor disk's forces as the LRM hands them over (Solver::set_cell_force_columns): the device sums
// the columns in a kernel with the coefficients as its argument; the host sums the same terms in the
// same order (column_series.hpp), so the forces and the flows must agree, also after new coefficients.
TEST(CudaBackend, ColumnForcesMatchCpu) {
  if (!cuda_available()) GTEST_SKIP() << "no CUDA device: run scripts/gpu_check.sh on a GPU machine";
  Lattice lat(periodic_config(24, 20, 16, 0.02f));
  auto cpu = make_cpu_solver(lat);
  auto gpu = make_cuda_solver(lat);
  const std::vector<std::uint32_t> cells = disk_like_cells(lat);
  const int columns = 5;
  std::vector<float> basis(columns * cells.size());
  for (int m = 0; m < columns; ++m)
    for (std::size_t k = 0; k < cells.size(); ++k) basis[m * cells.size() + k] = std::cos(0.3f * static_cast<float>(m * k)) / 64.0f;
  std::vector<float> c = {1e-4f, 0, -0.02f, 0, 2e-3f, 0.02f, -1e-3f, 0, 0, 0, 0, 0.01f, 5e-4f, -5e-4f, 0};
  for (Solver* s : {cpu.get(), gpu.get()}) {
    s->set_cell_force_columns(cells, basis, columns);
    s->set_cell_force_coefficients(c);
  }
  compare(*cpu, *gpu, 1, 1e-6);
  compare(*cpu, *gpu, 19, 1e-5);
  for (float& v : c) v *= -0.5f;
  for (Solver* s : {cpu.get(), gpu.get()}) s->set_cell_force_coefficients(c);
  compare(*cpu, *gpu, 1, 1e-6);
  compare(*cpu, *gpu, 19, 1e-5);
}

// What the LRM changes between steps, on a running flow: new face values (the impedance outlet's
// reference moves, so its outward change is stepped once: Solver::set_boundary_values), a new frame
// motion, and the listed-cell forces; each followed by single steps of both parities.
TEST(CudaBackend, MatchesCpuWhenFacesFramesAndForcesChangeBetweenSteps) {
  if (!cuda_available()) GTEST_SKIP() << "no CUDA device: run scripts/gpu_check.sh on a GPU machine";
  auto cpu = make_cpu_solver(every_boundary_case());
  auto gpu = make_cuda_solver(every_boundary_case());
  compare(*cpu, *gpu, 3, 1e-6);
  std::vector<float> values = cpu->boundary_values();
  ASSERT_EQ(values, gpu->boundary_values());
  const auto& cells = cpu->lattice().boundary_cells();
  for (std::size_t b = 0; b < cells.size(); ++b) {
    const auto t = static_cast<CellType>(cpu->lattice().types()[cells[b]] & ~kGeneralBit);
    if (t == CellType::PressureOutlet)
      values[4 * b] += 0.002f;
    else
      for (int a = 0; a < 3; ++a) values[4 * b + a] += 0.004f * static_cast<float>(a + 1);
  }
  for (Solver* s : {cpu.get(), gpu.get()}) s->set_boundary_values(values);
  EXPECT_EQ(cpu->boundary_values(), gpu->boundary_values());
  compare(*cpu, *gpu, 1, 1e-6);
  compare(*cpu, *gpu, 1, 1e-6);
  compare(*cpu, *gpu, 20, 1e-5);
  FrameMotion frame;
  frame.omega = {0.0f, 0.0f, 1e-3f};
  frame.centre = {20.0f, 12.0f, 10.0f};
  for (Solver* s : {cpu.get(), gpu.get()}) s->set_frame_motion(frame);
  compare(*cpu, *gpu, 1, 1e-6);
  frame.omega[2] = 1.5e-3f;
  frame.omega_dot[2] = 5e-4f;
  for (Solver* s : {cpu.get(), gpu.get()}) s->set_frame_motion(frame);
  compare(*cpu, *gpu, 1, 1e-6);
  std::vector<std::uint32_t> listed;
  for (int y = 8; y < 16; ++y)
    for (int x = 26; x < 34; ++x) listed.push_back(static_cast<std::uint32_t>(cpu->lattice().index(x, y, 14)));
  std::vector<float> f(3 * listed.size(), 0.0f);
  for (std::size_t k = 0; k < listed.size(); ++k) f[3 * k + 2] = -1e-4f;
  for (Solver* s : {cpu.get(), gpu.get()}) s->set_cell_forces(listed, f);
  compare(*cpu, *gpu, 1, 1e-6);
  compare(*cpu, *gpu, 20, 1e-5);
  EXPECT_EQ(cpu->velocities(listed), gpu->velocities(listed));
}
