// Walls that change while the flow runs (Solver::change_walls): a moving body re-voxelised in
// place, the refill of the cells it leaves, and the flow's history kept everywhere else.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "flow_cases.hpp"
#include "ship_lrm/lbm/refill.hpp"
#include "ship_lrm/lbm/solver.hpp"

namespace ship_lrm::lbm {
namespace {

using test::periodic_config;

// A cube of edge `edge` cells whose low corner is at x0 (cell-centre coordinates, wrapping in x),
// y and z fixed: the lattice of cfg with the cube's cells as a moving wall of velocity (v, 0, 0).
Lattice cube_lattice(const LatticeConfig& cfg, double x0, int edge, float v) {
  Lattice lat(cfg);
  WallMotion m;
  m.v[0] = v;
  const int wall = lat.add_wall_motion(m);
  for (int i = 0; i < cfg.nx; ++i) {
    const double d = std::fmod(i - x0 + 10.0 * cfg.nx, cfg.nx);  // distance behind the corner, wrapped
    if (d >= edge) continue;
    for (int k = 3; k < 3 + edge; ++k)
      for (int j = 3; j < 3 + edge; ++j) lat.set_moving_wall(i, j, k, wall);
  }
  return lat;
}

// Galilean invariance: a body moving with a uniform stream leaves it uniform. Bounce-back with
// Ladd's moving-wall term reflects the stream's equilibrium exactly (its odd part is 6 w rho c.u),
// so any departure comes from the cells the body leaves (the refill: mean of the neighbours, at
// equilibrium) and from the slots they are written to, which depend on the step's parity (A-A
// pattern): written the wrong way round, a freed cell would carry -u.
TEST(InPlaceWalls, BodyMovingWithTheStreamLeavesItUniform) {
  const float U = 0.07f;  // one cell every 14.3 steps: changes after even and odd steps
  LatticeConfig cfg = periodic_config(24, 12, 12, 0.02f);
  const int edge = 4;
  auto solver = make_cpu_solver(cube_lattice(cfg, 2.0, edge, U));
  const std::size_t n = solver->lattice().cells();
  std::vector<float> u(3 * n, 0.0f);
  for (std::size_t c = 0; c < n; ++c) u[3 * c] = U;
  solver->initialize({}, u);
  int changes[2] = {0, 0};
  for (int s = 1; s <= 200; ++s) {
    solver->step(1);
    Lattice next = cube_lattice(cfg, 2.0 + U * s, edge, U);
    bool same = true;
    for (std::size_t c = 0; c < n && same; ++c)
      same = is_wall(static_cast<CellType>(next.types()[c])) == is_wall(static_cast<CellType>(solver->lattice().types()[c] & ~kGeneralBit));
    if (same) continue;
    ASSERT_TRUE(solver->change_walls(next));
    ++changes[s % 2];
  }
  EXPECT_GT(changes[0], 2);
  EXPECT_GT(changes[1], 2);
  const Fields f = solver->fields();
  double worst = 0, worst_rho = 0;
  for (std::size_t c = 0; c < n; ++c) {
    if (is_wall(static_cast<CellType>(solver->lattice().types()[c] & ~kGeneralBit))) continue;
    worst = std::max({worst, std::abs(double(f.u[3 * c]) - U), std::abs(double(f.u[3 * c + 1])), std::abs(double(f.u[3 * c + 2]))});
    worst_rho = std::max(worst_rho, std::abs(f.rho[c] - 1.0));
  }
  EXPECT_LT(worst, 1e-3 * U);
  EXPECT_LT(worst_rho, 1e-5);
}

// The rest of the flow keeps its populations, stresses included: a decaying shear wave whose lattice
// is handed over again at every step decays at the analytic viscous rate nu k^2 and exactly as
// without the hand-overs. (A restart at equilibrium, the rebuild, would drop the shear stress at
// each hand-over.)
TEST(InPlaceWalls, TheFlowKeepsItsHistory) {
  const float nu = 0.05f, U = 0.02f;
  const int ny = 32;
  LatticeConfig cfg = periodic_config(4, ny, 4, nu);
  const double k = 2.0 * M_PI / ny;
  auto start = [&](Solver& s) {
    const std::size_t n = s.lattice().cells();
    std::vector<float> u(3 * n, 0.0f);
    for (std::size_t c = 0; c < n; ++c) u[3 * c] = U * static_cast<float>(std::sin(k * static_cast<double>((c / 4) % ny)));
    s.initialize({}, u);
  };
  auto plain = make_cpu_solver(Lattice(cfg));
  auto handed = make_cpu_solver(Lattice(cfg));
  start(*plain);
  start(*handed);
  const int steps = 400;
  for (int s = 0; s < steps; ++s) {
    plain->step(1);
    handed->step(1);
    Lattice next(cfg);
    ASSERT_TRUE(handed->change_walls(next));
  }
  const Fields a = plain->fields(), b = handed->fields();
  EXPECT_EQ(a.u, b.u);
  // amplitude of the sine (least squares over the cells)
  double num = 0, den = 0;
  for (std::size_t c = 0; c < b.rho.size(); ++c) {
    const double sn = std::sin(k * static_cast<double>((c / 4) % ny));
    num += b.u[3 * c] * sn;
    den += sn * sn;
  }
  const double expected = U * std::exp(-nu * k * k * steps);
  EXPECT_NEAR(num / den, expected, 0.01 * expected);
}

// With restart_flow the solver restarts as a new one made on the new lattice and started from
// restart_fields (its fields, the cells that leave the body refilled) would: the same populations,
// bit for bit, and the step count at 0.
TEST(InPlaceWalls, RestartEqualsANewSolver) {
  const float U = 0.05f;
  LatticeConfig cfg = periodic_config(20, 12, 12, 0.02f);
  cfg.faces[0].type = FaceType::VelocityInlet;
  cfg.faces[0].velocity = {U, 0, 0};
  cfg.faces[1].type = FaceType::ImpedanceOutlet;
  auto solver = make_cpu_solver(cube_lattice(cfg, 6.0, 4, 0.0f));
  solver->step(31);  // an odd count: the populations in the odd step's layout
  Lattice next = cube_lattice(cfg, 7.5, 4, 0.0f);
  Lattice copy = cube_lattice(cfg, 7.5, 4, 0.0f);
  std::vector<std::uint32_t> freed;
  for (std::size_t c = 0; c < next.cells(); ++c)
    if (is_wall(static_cast<CellType>(solver->lattice().types()[c] & ~kGeneralBit)) && !is_wall(static_cast<CellType>(next.types()[c])))
      freed.push_back(static_cast<std::uint32_t>(c));
  ASSERT_GT(freed.size(), 16u);  // the cube moved by 1.5 cells: two layers leave it
  const Fields carried = restart_fields(solver->lattice(), solver->fields(), freed);
  auto fresh = make_cpu_solver(std::move(copy));
  fresh->set_boundary_values(solver->boundary_values());
  fresh->initialize(carried.rho, carried.u);
  ASSERT_TRUE(solver->change_walls(next, true));
  EXPECT_EQ(solver->steps_done(), 0);
  EXPECT_EQ(solver->populations(), fresh->populations());
  solver->step(5);
  fresh->step(5);
  EXPECT_EQ(solver->fields().u, fresh->fields().u);
}

// Anything but the walls differs: refused, the solver untouched.
TEST(InPlaceWalls, RefusesAnotherLattice) {
  LatticeConfig cfg = periodic_config(12, 10, 10, 0.02f);
  cfg.faces[0].type = FaceType::VelocityInlet;
  cfg.faces[0].velocity = {0.03f, 0, 0};
  cfg.faces[1].type = FaceType::PressureOutlet;
  auto solver = make_cpu_solver(Lattice(cfg));
  solver->step(3);
  const std::vector<float> before = solver->populations();
  {
    LatticeConfig other = cfg;
    other.nx = 14;
    Lattice next(other);
    EXPECT_FALSE(solver->change_walls(next));
  }
  {
    LatticeConfig other = cfg;
    other.collision.nu = 0.03f;
    Lattice next(other);
    EXPECT_FALSE(solver->change_walls(next));
  }
  {
    Lattice next(cfg);
    next.set_wall(0, 4, 4);  // an inlet cell becomes a wall: other open-boundary cells
    EXPECT_FALSE(solver->change_walls(next));
    EXPECT_EQ(next.type(0, 4, 4), CellType::Wall);  // kept for a new solver
  }
  {
    Lattice next(cfg);
    next.add_wall_motion(WallMotion{});  // another number of wall motions
    EXPECT_FALSE(solver->change_walls(next));
  }
  EXPECT_EQ(solver->populations(), before);
  EXPECT_EQ(solver->steps_done(), 3);
}

// Ladd's moving-wall term with the fluid's density as rho_w (WallMotion::local_density = 1; Ladd
// 1994, eq. 3.2): a stream at a density other than the reference passing through a wall that moves
// with it along its normal (the wall a body's clipped face makes in the LRM's layers kept clear) is
// a steady state, since the stream's equilibrium reflects exactly (f_eq_i - f_eq_opp(i) =
// 6 w_i rho c_i.u). With the reference density (0, the default) the wall takes out u_n where the
// stream brings rho u_n, and the density drifts.
TEST(InPlaceWalls, WallMovingAlongItsNormalWithAStreamOfAnyDensityLeavesItAsItIs) {
  const float U = 0.04f, rho0 = 1.05f;
  auto drift = [&](float local_density) {
    LatticeConfig cfg = periodic_config(16, 6, 6, 0.02f);
    Lattice lat(cfg);
    WallMotion m;
    m.v[0] = U;
    m.local_density = local_density;
    const int wall = lat.add_wall_motion(m);
    for (int z = 0; z < 6; ++z)
      for (int y = 0; y < 6; ++y) lat.set_moving_wall(0, y, z, wall);
    auto solver = make_cpu_solver(std::move(lat));
    const std::size_t n = solver->lattice().cells();
    std::vector<float> u(3 * n, 0.0f);
    for (std::size_t c = 0; c < n; ++c) u[3 * c] = U;
    solver->initialize(std::vector<float>(n, rho0), u);
    solver->step(201);  // even and odd steps
    const Fields f = solver->fields();
    double worst = 0;
    for (std::size_t c = 0; c < n; ++c) {
      if (is_wall(static_cast<CellType>(solver->lattice().types()[c] & ~kGeneralBit))) continue;
      worst = std::max({worst, std::abs(f.rho[c] - static_cast<double>(rho0)), std::abs(f.u[3 * c] - static_cast<double>(U)),
                        std::abs(double(f.u[3 * c + 1])), std::abs(double(f.u[3 * c + 2]))});
    }
    return worst;
  };
  EXPECT_LT(drift(1.0f), 1e-5);
  EXPECT_GT(drift(0.0f), 1e-3);  // the reference density: (rho - 1) u_n per step and wall cell
}

}  // namespace
}  // namespace ship_lrm::lbm
