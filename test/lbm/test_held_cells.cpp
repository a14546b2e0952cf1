// Held cells (Lattice::set_held): fluid inside a body where no wall may stand, whose every emitted
// population is the equilibrium with its own mass and the body's velocity. The LRM uses them in the
// two outermost layers, where a ship is kept clear of the faces (thesis 6.4).
#include <gtest/gtest.h>

#include <cmath>

#include "flow_cases.hpp"
#include "ship_lrm/lbm/solver.hpp"

namespace ship_lrm::lbm {
namespace {

using test::periodic_config;

// A plane of held cells at y = 0 set moving along x at U at t = 0 in fluid at rest: Stokes' first
// problem, u(y, t) = U erfc(|y| / (2 sqrt(nu t))) on both sides of the plane (periodic in y, so the
// other side is y < 0; the two fronts stay far apart). Returns the largest error over y / U after
// `steps` steps on a lattice of ny cells across.
double stokes_first_problem_error(int ny, long steps, float nu, float U) {
  LatticeConfig cfg = periodic_config(3, ny, 3, nu);
  Lattice lat(cfg);
  WallMotion plate;
  plate.v[0] = U;
  const int w = lat.add_wall_motion(plate);
  for (int z = 0; z < 3; ++z)
    for (int x = 0; x < 3; ++x) lat.set_held(x, 0, z, w);
  auto solver = make_cpu_solver(std::move(lat));
  solver->step(steps);
  const Fields f = solver->fields();
  const double t = static_cast<double>(steps), delta = 2.0 * std::sqrt(nu * t);
  double worst = 0;
  for (int y = 1; y < ny; ++y) {
    const double d = std::min(y, ny - y);  // distance from the plate, either side
    const double exact = U * std::erfc(d / delta);
    worst = std::max(worst, std::abs(f.u[3 * solver->lattice().index(0, y, 0)] - exact) / U);
  }
  return worst;
}

// The held plane drives the fluid like the plate of Stokes' first problem (the analytic solution),
// after an even and after an odd number of steps (a held cell's emissions sit in other slots after
// each). A held cell is an equilibrium node: it sends no shear stress, a first-order boundary, so
// the error falls as the cell size under diffusive refinement (twice the cells across, four times
// the steps: the same nu t / L^2) and is bounded as a displacement of the plate: the error divided
// by the analytic slope at the plate, U 2 / (sqrt(pi) delta), must stay below a quarter cell.
TEST(HeldCells, PlaneMovingAlongItselfIsStokesFirstProblem) {
  const float nu = 0.1f, U = 0.05f;
  const double coarse = stokes_first_problem_error(96, 200, nu, U);
  const double coarse_odd = stokes_first_problem_error(96, 201, nu, U);
  const double fine = stokes_first_problem_error(192, 800, nu, U);
  auto cells = [&](double err, long steps) { return err / (2.0 / std::sqrt(M_PI) / (2.0 * std::sqrt(nu * steps))); };
  std::printf(
      "max |u - U erfc| / U: %.4g (ny 96, 200 steps; plate off by %.3f cells), %.4g (201 steps), %.4g (ny 192, 800 steps; %.3f cells)\n",
      coarse, cells(coarse, 200), coarse_odd, fine, cells(fine, 800));
  EXPECT_LT(cells(coarse, 200), 0.25);
  EXPECT_LT(cells(coarse_odd, 201), 0.25);
  EXPECT_LT(cells(fine, 800), 0.25);
  EXPECT_LT(fine, coarse / 1.8);  // first order or better
}

// Held cells keep the mass they hold: a closed box (no-slip walls on every face) with a spinning
// block of held cells inside conserves the total mass to float rounding.
TEST(HeldCells, ConserveMass) {
  LatticeConfig cfg = periodic_config(16, 16, 16, 0.02f);
  for (auto& f : cfg.faces) f.type = FaceType::Wall;
  Lattice lat(cfg);
  WallMotion spin;
  spin.omega[2] = 0.01f;
  spin.centre[0] = spin.centre[1] = spin.centre[2] = 7.5f;
  const int w = lat.add_wall_motion(spin);
  for (int z = 5; z < 11; ++z)
    for (int y = 5; y < 11; ++y)
      for (int x = 5; x < 11; ++x) lat.set_held(x, y, z, w);
  lat.set_held(0, 0, 0, Lattice::kHeldAtRest);  // a corner cell, next to the box walls
  auto solver = make_cpu_solver(std::move(lat));
  const double m0 = test::total_mass(solver->fields());
  solver->step(301);
  const Fields f = solver->fields();
  EXPECT_NEAR(test::total_mass(f) / m0, 1.0, 1e-5);
  // and the fluid has been set turning with the block
  const std::size_t c = solver->lattice().index(12, 8, 8);  // +x of the axis: u_y > 0 for omega_z > 0
  EXPECT_GT(f.u[3 * c + 1], 0.0f);
}

TEST(HeldCells, OnlyPlainFluidCellsOnceWithAKnownMotion) {
  LatticeConfig cfg = periodic_config(8, 8, 8, 0.02f);
  cfg.faces[0].type = FaceType::VelocityInlet;
  cfg.faces[1].type = FaceType::PressureOutlet;
  {
    Lattice lat(cfg);
    lat.set_wall(3, 3, 3);
    lat.set_held(3, 3, 3, Lattice::kHeldAtRest);
    EXPECT_THROW(lat.finalize(), ConfigError);
  }
  {
    Lattice lat(cfg);
    lat.set_held(0, 3, 3, Lattice::kHeldAtRest);  // an inlet cell
    EXPECT_THROW(lat.finalize(), ConfigError);
  }
  {
    Lattice lat(cfg);
    lat.set_held(4, 4, 4, Lattice::kHeldAtRest);
    lat.set_held(4, 4, 4, Lattice::kHeldAtRest);
    EXPECT_THROW(lat.finalize(), ConfigError);
  }
  {
    Lattice lat(cfg);
    EXPECT_THROW(lat.set_held(4, 4, 4, 0), ConfigError);  // no wall motion added
    EXPECT_THROW(lat.set_held(8, 4, 4, Lattice::kHeldAtRest), ConfigError);
  }
}

}  // namespace
}  // namespace ship_lrm::lbm
