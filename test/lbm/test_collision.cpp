// The collision operators of cell_ops.hpp checked against their moment definitions, with moment
// sums written here independently (full sums over the 19 directions of the unshifted f = g + w).
// The recursive regularised collision (Malaspinas 2015; Coreixas et al. 2017, Phys. Rev. E 96,
// 033306) must relax mass, momentum and the momentum flux exactly as BGK with Guo forcing does (same
// Navier-Stokes limit, same viscosity), give the third-order moments of its recursion, and leave no
// component outside the 16 Hermite polynomials D3Q19 holds (the "ghost" moments BGK carries along).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <random>
#include <vector>

#include "ship_lrm/lbm/cell_ops.hpp"
#include "ship_lrm/lbm/solver.hpp"

using namespace ship_lrm::lbm;
using ship_lrm::ConfigError;

namespace {

using Pops = std::array<float, Q>;

int c(int i, int a) { return d3q19::c(i, a); }

// sum_i f_i P_i for the unshifted f of shifted populations g
double moment(const Pops& g, const std::function<double(int)>& P) {
  double s = 0;
  for (int i = 0; i < Q; ++i) s += (g[i] + d3q19::w(i)) * P(i);
  return s;
}

// A random pre-collision cell: populations about a moving equilibrium (rho near 1, u of size
// `speed`, non-equilibrium parts of 0.05 w_i in every direction, ghost moments included), a force
// density of up to 1e-3 per component, and the state with the Guo half-force shift.
struct RandomCell {
  Pops g;
  float F[3];
  Macro m;
};
RandomCell random_cell(std::mt19937& rng, float speed) {
  std::uniform_real_distribution<float> d(-1.0f, 1.0f);
  const float u[3] = {speed * d(rng), speed * d(rng), speed * d(rng)};
  RandomCell r;
  for (int i = 0; i < Q; ++i) r.g[i] = equilibrium(i, 1.0f + 0.02f * d(rng), u) + 0.05f * d3q19::w(i) * d(rng);
  for (float& f : r.F) f = 1e-3f * d(rng);
  r.m = macro_from_populations(r.g.data(), r.F);
  return r;
}

// Third-order Hermite polynomials D3Q19 holds (per odd axis b): P+ = c_b (c_a1^2 + c_a2^2 - 2/3) and
// P- = c_b (c_a1^2 - c_a2^2), a1 = b + 1, a2 = b + 2 (mod 3).
double p_plus(int i, int b) {
  const int a1 = (b + 1) % 3, a2 = (b + 2) % 3;
  return c(i, b) * (c(i, a1) * c(i, a1) + c(i, a2) * c(i, a2) - 2.0 / 3.0);
}
double p_minus(int i, int b) {
  const int a1 = (b + 1) % 3, a2 = (b + 2) % 3;
  return c(i, b) * (c(i, a1) * c(i, a1) - c(i, a2) * c(i, a2));
}

// The 16 Hermite polynomials D3Q19 holds: 1, c, H2 (6), P+ and P- (3 each).
std::vector<std::function<double(int)>> hermite_basis() {
  std::vector<std::function<double(int)>> basis = {[](int) { return 1.0; }};
  for (int a = 0; a < 3; ++a) basis.push_back([a](int i) { return static_cast<double>(c(i, a)); });
  for (int a = 0; a < 3; ++a) basis.push_back([a](int i) { return c(i, a) * c(i, a) - 1.0 / 3.0; });
  for (int a = 0; a < 3; ++a)
    for (int b = a + 1; b < 3; ++b) basis.push_back([a, b](int i) { return static_cast<double>(c(i, a) * c(i, b)); });
  for (int b = 0; b < 3; ++b) {
    basis.push_back([b](int i) { return p_plus(i, b); });
    basis.push_back([b](int i) { return p_minus(i, b); });
  }
  return basis;
}

// Largest |f_i - its projection onto the Hermite polynomials| (each term w_i P_i (sum_j P_j f_j) /
// (sum_j w_j P_j^2)): the populations' ghost content.
double ghost_content(const Pops& g) {
  double off = 0;
  for (int i = 0; i < Q; ++i) {
    double proj = 0;
    for (const auto& P : hermite_basis()) {
      double norm = 0;
      for (int j = 0; j < Q; ++j) norm += d3q19::w(j) * P(j) * P(j);
      proj += d3q19::w(i) * P(i) * moment(g, P) / norm;
    }
    off = std::max(off, std::fabs(g[i] + d3q19::w(i) - proj));
  }
  return off;
}

}  // namespace

// Both collisions, same random pre-collision populations and force: density, momentum (j + F) and the
// momentum flux sum c_a c_b f after the collision agree to float round-off.
TEST(Collision, RecursiveRegularisedRelaxesTheHydrodynamicMomentsAsBgk) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 50; ++trial) {
    for (float nu : {1e-7f, 0.01f, 1.0f / 6.0f}) {
      for (float smagorinsky : {0.0f, 0.05f}) {
        const RandomCell r = random_cell(rng, 0.15f);
        const Pops& g0 = r.g;
        const float* F = r.F;
        const Macro& m = r.m;
        CollisionParams p;
        p.nu = nu;
        p.smagorinsky = smagorinsky;
        Pops bgk = g0, rr = g0;
        collide(bgk.data(), m, F, p);
        p.model = CollisionModel::RecursiveRegularized;
        collide(rr.data(), m, F, p);
        EXPECT_NEAR(moment(rr, [](int) { return 1.0; }), moment(bgk, [](int) { return 1.0; }), 2e-6);
        for (int a = 0; a < 3; ++a) {
          const double j0 = moment(g0, [&](int i) { return c(i, a); });
          EXPECT_NEAR(moment(bgk, [&](int i) { return c(i, a); }), j0 + F[a], 1e-6);
          EXPECT_NEAR(moment(rr, [&](int i) { return c(i, a); }), j0 + F[a], 1e-6);
          for (int b = 0; b < 3; ++b) {
            const auto cc = [&](int i) { return static_cast<double>(c(i, a) * c(i, b)); };
            EXPECT_NEAR(moment(rr, cc), moment(bgk, cc), 2e-6) << "Pi_" << a << b << " nu " << nu << " s " << smagorinsky;
          }
        }
      }
    }
  }
}

// The third-order moments after the recursive regularised collision are those of the recursion,
// rho u_a u_a u_b + (1 - omega) (2 u_a a2_ab + u_b a2_aa) with a2 = Pi_neq + (u F + F u) / 2,
// combined as P+ and P-; Pi_neq from the full sums here. Also the ghosts: the post-collision f equals
// its own projection onto the 16 Hermite polynomials (1, c, H2, P+, P-).
TEST(Collision, RecursiveRegularisedGivesTheRecursionsThirdMomentsAndNoGhosts) {
  std::mt19937 rng(11);
  for (int trial = 0; trial < 50; ++trial) {
    const RandomCell r = random_cell(rng, 0.2f);
    const Pops& g0 = r.g;
    const float* F = r.F;
    const Macro& m = r.m;
    CollisionParams p;
    p.nu = 0.02f;
    p.model = CollisionModel::RecursiveRegularized;
    Pops g = g0;
    collide(g.data(), m, F, p);
    const double omega = omega_from_nu(p.nu), keep = 1.0 - omega;
    const double u[3] = {m.u[0], m.u[1], m.u[2]};
    double a2[3][3];
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) {
        double s = 0;
        for (int i = 0; i < Q; ++i) s += c(i, a) * c(i, b) * (static_cast<double>(g0[i]) - equilibrium(i, m.rho, m.u));
        a2[a][b] = s + 0.5 * (u[a] * F[b] + u[b] * F[a]);
      }
    const auto a3 = [&](int a, int b) { return m.rho * u[a] * u[a] * u[b] + keep * (2.0 * u[a] * a2[a][b] + u[b] * a2[a][a]); };
    for (int b = 0; b < 3; ++b) {
      const int a1 = (b + 1) % 3, a2i = (b + 2) % 3;
      EXPECT_NEAR(moment(g, [&](int i) { return p_plus(i, b); }), a3(a1, b) + a3(a2i, b), 2e-6) << "b " << b;
      EXPECT_NEAR(moment(g, [&](int i) { return p_minus(i, b); }), a3(a1, b) - a3(a2i, b), 2e-6) << "b " << b;
    }
    EXPECT_LE(ghost_content(g), 2e-6);
    // BGK keeps the ghosts of the random start: its f is not its own projection
    Pops bgk = g0;
    p.model = CollisionModel::Bgk;
    collide(bgk.data(), m, F, p);
    EXPECT_GT(ghost_content(bgk), 1e-4);
  }
}

// At rest, with a non-equilibrium part that is purely second order (the viscous stress of a shear),
// there is nothing for the regularisation to remove: the two collisions agree population by population.
TEST(Collision, RecursiveRegularisedEqualsBgkForAPureViscousStressAtRest) {
  const float u[3] = {0, 0, 0};
  const float S[6] = {1e-3f, -4e-4f, -6e-4f, 5e-4f, -2e-4f, 3e-4f};  // strain rate xx yy zz xy xz yz
  Pops g0;
  reconstruct_fd(g0.data(), 1.0f, u, S, 1.9f);
  const float F[3] = {0, 0, 0};
  const Macro m = macro_from_populations(g0.data(), F);
  CollisionParams p;
  p.nu = 1e-3f;
  Pops bgk = g0, rr = g0;
  collide(bgk.data(), m, F, p);
  p.model = CollisionModel::RecursiveRegularized;
  collide(rr.data(), m, F, p);
  for (int i = 0; i < Q; ++i) EXPECT_NEAR(rr[i], bgk[i], 1e-8) << "direction " << i;
}

TEST(Collision, KindAndNames) {
  EXPECT_EQ(hermite_basis().size(), 16u);
  CollisionParams p;
  EXPECT_EQ(collision_kind(p), 0);
  p.smagorinsky = 0.05f;
  EXPECT_EQ(collision_kind(p), kSmagorinskyBit);
  p.model = CollisionModel::RecursiveRegularized;
  EXPECT_EQ(collision_kind(p), kSmagorinskyBit | kRecursiveBit);
  EXPECT_EQ(parse_collision_model("recursive"), CollisionModel::RecursiveRegularized);
  EXPECT_EQ(parse_collision_model("bgk"), CollisionModel::Bgk);
  EXPECT_STREQ(to_string(CollisionModel::RecursiveRegularized), "recursive");
  EXPECT_THROW(parse_collision_model("mrt"), ConfigError);
}
