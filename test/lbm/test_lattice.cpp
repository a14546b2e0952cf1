// Lattice descriptor, set-up validation (bad input), divergence guard and output.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>

#include "flow_cases.hpp"
#include "ship_lrm/lbm/lattice_view.hpp"
#include "ship_lrm/lbm/vtk_writer.hpp"

using namespace ship_lrm::lbm;
using ship_lrm::ConfigError;
using namespace ship_lrm::lbm::test;

// Isotropy of D3Q19 (Qian, d'Humieres & Lallemand 1992): sum w = 1, sum w c = 0,
// sum w c_a c_b = cs^2 delta_ab, and opposite directions pair up.
TEST(Descriptor, MomentsAndOpposites) {
  double s0 = 0, s1[3] = {0, 0, 0}, s2[3][3] = {};
  for (int i = 0; i < Q; ++i) {
    s0 += d3q19::w(i);
    EXPECT_EQ(d3q19::cx(d3q19::opp(i)), -d3q19::cx(i));
    EXPECT_EQ(d3q19::cy(d3q19::opp(i)), -d3q19::cy(i));
    EXPECT_EQ(d3q19::cz(d3q19::opp(i)), -d3q19::cz(i));
    EXPECT_EQ(d3q19::index_of(d3q19::cx(i), d3q19::cy(i), d3q19::cz(i)), i);
    for (int a = 0; a < 3; ++a) {
      s1[a] += d3q19::w(i) * d3q19::c(i, a);
      for (int b = 0; b < 3; ++b) s2[a][b] += d3q19::w(i) * d3q19::c(i, a) * d3q19::c(i, b);
    }
  }
  EXPECT_NEAR(s0, 1.0, 1e-7);
  for (int a = 0; a < 3; ++a) {
    EXPECT_NEAR(s1[a], 0.0, 1e-7);
    for (int b = 0; b < 3; ++b) EXPECT_NEAR(s2[a][b], a == b ? 1.0 / 3.0 : 0.0, 1e-7);
  }
}

// The equilibrium reproduces rho and rho u exactly (thesis eqs. 6.8, 6.11, 6.12).
TEST(Descriptor, EquilibriumMoments) {
  const float u[3] = {0.05f, -0.02f, 0.03f};
  float g[Q];
  for (int i = 0; i < Q; ++i) g[i] = equilibrium(i, 1.02f, u);
  float rho, j[3];
  moments(g, rho, j);
  EXPECT_NEAR(rho, 1.02f, 1e-6);
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(j[a], 1.02f * u[a], 1e-7);
}

TEST(BadInput, RejectsInvalidSetups) {
  LatticeConfig ok = periodic_config(8, 8, 8, 0.1f);
  {
    auto c = ok;
    c.nx = 2;
    EXPECT_THROW(Lattice{c}, ConfigError);
  }
  {
    auto c = ok;
    c.collision.nu = 0.0f;  // tau = 1/2
    EXPECT_THROW(Lattice{c}, ConfigError);
    c.collision.nu = -0.1f;
    EXPECT_THROW(Lattice{c}, ConfigError);
    c.collision.nu = NAN;
    EXPECT_THROW(Lattice{c}, ConfigError);
  }
  {
    auto c = ok;
    c.faces[0].type = FaceType::Wall;  // +x still periodic
    EXPECT_THROW(Lattice{c}, ConfigError);
  }
  {
    auto c = ok;
    c.faces[0].type = FaceType::VelocityInlet;
    c.faces[1].type = FaceType::PressureOutlet;
    c.faces[0].velocity = {0.3f, 0, 0};  // Mach 0.52 > limit
    EXPECT_THROW(Lattice{c}, ConfigError);
    c.faces[0].velocity = {0.05f, 0, 0};
    c.faces[1].density = -1.0f;
    EXPECT_THROW(Lattice{c}, ConfigError);
  }
  {
    auto c = ok;
    c.faces[2].type = FaceType::MovingWall;
    c.faces[3].type = FaceType::Wall;
    c.faces[2].velocity = {0, 0.05f, 0};  // moving through itself
    EXPECT_THROW(Lattice{c}, ConfigError);
  }
  {
    Lattice lat(ok);
    EXPECT_THROW(lat.set_wall(8, 0, 0), ConfigError);
    EXPECT_THROW(lat.set_velocity_inlet(4, 4, 4, {0.01f, 0, 0}), ConfigError);  // not on a face (all periodic)
    EXPECT_THROW(lat.set_moving_wall(1, 1, 1, 0), ConfigError);                 // no such wall motion
  }
  EXPECT_THROW(parse_backend("gpu"), ConfigError);
  auto s = make_cpu_solver(Lattice(ok));
  EXPECT_THROW(s->initialize({1.0f}, {}), ConfigError);
  EXPECT_THROW(s->initialize({}, std::vector<float>(3 * 512, 0.5f)), ConfigError);  // above Mach limit
  EXPECT_THROW(s->set_force_field({1.0f, 2.0f}), ConfigError);
  EXPECT_THROW(s->set_uniform_force({NAN, 0, 0}), ConfigError);
}

TEST(BadInput, CudaRequestedWithoutDevice) {
  if (cuda_available()) GTEST_SKIP() << "a CUDA device is present";
  EXPECT_THROW(make_solver(Lattice(periodic_config(8, 8, 8, 0.1f)), Backend::Cuda), ConfigError);
  // auto falls back to the CPU
  EXPECT_STREQ(make_solver(Lattice(periodic_config(8, 8, 8, 0.1f)), Backend::Auto)->backend_name(), "cpu");
}

// The guard stops a diverging run with a clear error naming the step and the cell.
TEST(DivergenceGuard, NamesStepAndCell) {
  LatticeConfig cfg = periodic_config(8, 8, 8, 0.1f);
  cfg.guard_interval = 1;
  auto s = make_cpu_solver(Lattice(cfg));
  s->set_uniform_force({0.2f, 0, 0});  // accelerates the fluid beyond the speed of sound in a few steps
  try {
    s->step(100);
    FAIL() << "no divergence detected";
  } catch (const DivergenceError& e) {
    EXPECT_GT(e.step, 0);
    EXPECT_LT(e.step, 10);
    EXPECT_NE(std::string(e.what()).find("step"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("cell"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("density"), std::string::npos);
  }
}

// Mass is conserved in a closed box whose faces mix slip, no-slip and moving walls (edges and
// corners included) with wall cells and slip-wall cells inside: the reflection map is one-to-one.
TEST(Walls, ClosedBoxMixedWallsConservesMass) {
  LatticeConfig cfg = periodic_config(12, 10, 9, 0.05f);
  cfg.faces[0].type = FaceType::SlipWall;
  cfg.faces[1].type = FaceType::Wall;
  cfg.faces[2].type = FaceType::SlipWall;
  cfg.faces[3].type = FaceType::MovingWall;
  cfg.faces[3].velocity = {0.05f, 0, 0.02f};
  cfg.faces[4].type = FaceType::SlipWall;
  cfg.faces[5].type = FaceType::SlipWall;
  Lattice lat(cfg);
  for (int z = 0; z < 9; ++z) lat.set_slip_wall(6, 0, z);
  lat.set_wall(3, 4, 4);
  WallMotion spin;
  spin.omega[2] = 0.01f;
  spin.centre[0] = 8, spin.centre[1] = 5, spin.centre[2] = 4;
  lat.set_moving_wall(8, 5, 4, lat.add_wall_motion(spin));
  auto s = make_cpu_solver(lat);
  const double m0 = total_mass(s->fields());
  s->step(2000);
  const Fields f = s->fields();
  EXPECT_NEAR(total_mass(f) / m0, 1.0, 1e-5);
  EXPECT_GT(kinetic_energy(f), 0.0);  // the lid drives a flow
}

// The link mask finalize hands the solvers for every fluid-like cell (bit i: the neighbour at
// c + c_i is a wall or lies beyond a non-periodic face; kMovingWallLink: one of those moves), found
// here by walking to each neighbour, on a lattice that mixes periodic, moving-wall, wall and open
// faces with resting and moving wall cells inside, next to the faces too; and the lists of cells it
// hands them (segments, general cells, boundary cells) are in cell order.
TEST(Walls, LinkMasksMatchAWalkToEachNeighbour) {
  LatticeConfig cfg = periodic_config(7, 8, 9, 0.05f);  // x periodic
  cfg.faces[2].type = FaceType::MovingWall;
  cfg.faces[2].velocity = {0.02f, 0, 0};
  cfg.faces[3].type = FaceType::Wall;
  cfg.faces[4].type = FaceType::VelocityInlet;
  cfg.faces[4].velocity = {0, 0, 0.02f};
  cfg.faces[5].type = FaceType::ImpedanceOutlet;
  Lattice lat(cfg);
  lat.set_wall(3, 4, 4);
  lat.set_wall(0, 3, 5);  // on the periodic face: reached across it
  WallMotion spin;
  spin.omega[2] = 0.01f;
  const int slot = lat.add_wall_motion(spin);
  lat.set_moving_wall(5, 2, 3, slot);
  lat.set_moving_wall(6, 6, 2, slot);
  lat.finalize();
  const int n[3] = {cfg.nx, cfg.ny, cfg.nz};
  const auto base = [&](int x, int y, int z) { return static_cast<CellType>(lat.types()[lat.index(x, y, z)] & ~kGeneralBit); };
  const auto walked = [&](std::size_t c) {
    const int x = static_cast<int>(c % n[0]), y = static_cast<int>((c / n[0]) % n[1]), z = static_cast<int>(c / (n[0] * n[1]));
    std::uint32_t m = 0;
    for (int i = 1; i < Q; ++i) {
      int p[3] = {x + d3q19::cx(i), y + d3q19::cy(i), z + d3q19::cz(i)};
      bool wall = false, moving = false;
      for (int a = 0; a < 3; ++a) {
        if (p[a] >= 0 && p[a] < n[a]) continue;
        const FaceCondition& f = cfg.faces[2 * a + (p[a] >= n[a] ? 1 : 0)];
        if (f.type == FaceType::Periodic) {
          p[a] = (p[a] + n[a]) % n[a];
          continue;
        }
        wall = true;
        moving = moving || f.type == FaceType::MovingWall;
      }
      if (!wall) {
        const CellType t = base(p[0], p[1], p[2]);
        wall = t == CellType::Wall || t == CellType::SlipWall || t == CellType::MovingWall;
        moving = t == CellType::MovingWall;
      }
      if (wall) m |= 1u << i;
      if (moving) m |= kMovingWallLink;
    }
    return m;
  };
  std::size_t checked = 0, moving_links = 0;
  const auto check = [&](std::size_t c, std::uint32_t mask) {
    EXPECT_EQ(mask, walked(c)) << "cell " << c;
    moving_links += (mask & kMovingWallLink) != 0;
    ++checked;
  };
  for (const Segment& sg : lat.bulk_segments())
    for (std::uint32_t k = 0; k < sg.count; ++k) check(sg.first + k, sg.link_mask);
  for (std::size_t k = 0; k < lat.general_cells().size(); ++k) check(lat.general_cells()[k], lat.general_link_masks()[k]);
  for (std::size_t k = 0; k < lat.boundary_cells().size(); ++k) check(lat.boundary_cells()[k], lat.boundary_link_masks()[k]);
  std::size_t walls = 0;
  for (std::size_t c = 0; c < lat.cells(); ++c) {
    const CellType t = static_cast<CellType>(lat.types()[c] & ~kGeneralBit);
    walls += t == CellType::Wall || t == CellType::SlipWall || t == CellType::MovingWall;
  }
  EXPECT_EQ(checked + walls, lat.cells());  // every fluid-like cell once
  EXPECT_GT(moving_links, 2u * 7u);         // the moving face's row and the moving cells' neighbours
  // each list in cell order (finalize makes them by slabs of z in parallel and joins them; the solvers
  // find a cell's segment by binary search)
  const auto& segs = lat.bulk_segments();
  for (std::size_t k = 1; k < segs.size(); ++k) EXPECT_LT(segs[k - 1].first + segs[k - 1].count - 1, segs[k].first) << "segment " << k;
  const auto ascending = [](const std::vector<std::uint32_t>& v) {
    return std::adjacent_find(v.begin(), v.end(), std::greater_equal<>()) == v.end();
  };
  EXPECT_TRUE(ascending(lat.general_cells()));
  EXPECT_TRUE(ascending(lat.boundary_cells()));
}

// The VTK writer produces an image-data file (header and size) and reports unwritable paths.
TEST(Output, VtiFile) {
  auto s = make_cpu_solver(Lattice(periodic_config(6, 5, 4, 0.1f)));
  const std::string path = ::testing::TempDir() + "/ship_lrm_test.vti";
  write_vti(path, s->lattice(), s->fields(), 0.5);
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  ASSERT_TRUE(in.good());
  const auto size = static_cast<std::size_t>(in.tellg());
  EXPECT_GT(size, 120u * 4u * 4u);  // rho + 3 u + type for 120 cells
  in.seekg(0);
  std::string head(200, '\0');
  in.read(&head[0], 200);
  EXPECT_NE(head.find("ImageData"), std::string::npos);
  EXPECT_THROW(write_vti("/nonexistent-dir/x.vti", s->lattice(), s->fields()), std::runtime_error);
}
