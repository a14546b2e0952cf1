// Per-cell lattice-Boltzmann physics, written once for the CPU and CUDA backends.
//
// Populations are stored shifted by their rest weight, g_i = f_i - w_i (Lehmann et al. 2022,
// "Accuracy and performance of the lattice Boltzmann method with 64-bit, 32-bit, and customized
// 16-bit number formats", Phys. Rev. E 106, 015308), which keeps float32 round-off relative to the
// small deviations from rest instead of to 1. All formulas below are written for g.
#pragma once

#include <cmath>
#include <type_traits>

#include "ship_lrm/lbm/d3q19.hpp"

#if defined(__CUDACC__)
#define SHIP_LRM_UNROLL _Pragma("unroll")
#elif defined(__GNUC__) && !defined(__clang__)
#define SHIP_LRM_UNROLL _Pragma("GCC unroll 19")
#else
#define SHIP_LRM_UNROLL
#endif

namespace ship_lrm::lbm {

using d3q19::Q;

// Density and velocity of one cell (lattice units).
struct Macro {
  float rho = 1.0f;
  float u[3] = {0.0f, 0.0f, 0.0f};
};

// The collision operator (docs/design.md, "The collision"):
// - Bgk: single relaxation time, thesis eq. 6.9.
// - RecursiveRegularized: the non-equilibrium part is rebuilt from its second-order moment and the
//   third-order moments the recursion of Malaspinas 2015 gives, the equilibrium carries the
//   third-order terms D3Q19 supports (Coreixas, Wissocq, Puigt, Boussuge & Sagaut 2017, Phys. Rev. E
//   96, 033306). Same viscosity as BGK, but a uniform stream near tau = 1/2 stays stable to Mach 0.3,
//   where BGK's grows (docs/benchmarks.md at 193c1b4, "The recursive regularised collision").
enum class CollisionModel : int { Bgk = 0, RecursiveRegularized = 1 };

// Collision parameters in lattice units.
struct CollisionParams {
  float nu = 1.0f / 6.0f;    // kinematic viscosity; omega = 1 / (3 nu + 1/2) (thesis eq. 6.7)
  float smagorinsky = 0.0f;  // Smagorinsky constant s (0: none)
  CollisionModel model = CollisionModel::Bgk;
};

// The collision as a template argument of the update loops (no branch per cell): bit 0 the
// Smagorinsky model, bit 1 the recursive regularisation.
constexpr int kSmagorinskyBit = 1, kRecursiveBit = 2;
SHIP_LRM_HD constexpr int collision_kind(const CollisionParams& p) {
  return (p.smagorinsky > 0.0f ? kSmagorinskyBit : 0) | (p.model == CollisionModel::RecursiveRegularized ? kRecursiveBit : 0);
}
// Calls f(std::integral_constant<int, kind>) with the kind of p (the backends' run-time dispatch; host only).
template <class F>
void with_collision_kind(const CollisionParams& p, F&& f) {
  switch (collision_kind(p)) {
    case 0:
      f(std::integral_constant<int, 0>());
      break;
    case 1:
      f(std::integral_constant<int, 1>());
      break;
    case 2:
      f(std::integral_constant<int, 2>());
      break;
    default:
      f(std::integral_constant<int, 3>());
      break;
  }
}

SHIP_LRM_HD float omega_from_nu(float nu) { return 1.0f / (3.0f * nu + 0.5f); }

// Lattice sums without their zero terms. A D3Q19 velocity component is -1, 0 or 1, and once the
// direction loops are unrolled the compiler knows which; but it may not drop 0 * x in IEEE
// arithmetic (x could be NaN or -0), so c_i . v written as a product computes every zero term
// (about a third of the arithmetic of a collision). These give the same values, without them.
// s += c x for an integer c known at compile time:
SHIP_LRM_HD void add_times(float& s, int c, float x) {
  if (c == 1)
    s += x;
  else if (c == -1)
    s -= x;
  else if (c != 0)
    s += static_cast<float>(c) * x;
}
// c_i . v, summed over the axes in order as the product would be:
SHIP_LRM_HD float lattice_dot(int i, const float v[3]) {
  float s = 0.0f;
  bool first = true;
  for (int a = 0; a < 3; ++a) {
    const int c = d3q19::c(i, a);
    if (c == 0) continue;
    const float t = c == 1 ? v[a] : (c == -1 ? -v[a] : static_cast<float>(c) * v[a]);
    s = first ? t : s + t;
    first = false;
  }
  return s;
}

// Discrete equilibrium, thesis eq. 6.8, minus the rest weight w_i, as its parts even and odd in c_i:
// direction i has even + odd, its opposite (c = -c_i, same weight) even - odd, so the collision
// evaluates the formula once per pair of directions. uu = |u|^2.
struct EvenOddParts {  // a per-direction term split into its parts even and odd in c_i
  float even, odd;
};
SHIP_LRM_HD EvenOddParts equilibrium_parts(int i, float rho, const float u[3], float uu) {
  const float cu = lattice_dot(i, u);
  const float w = d3q19::w(i);
  return {w * ((rho - 1.0f) + rho * (4.5f * cu * cu - 1.5f * uu)), i == 0 ? 0.0f : w * rho * (3.0f * cu)};
}
SHIP_LRM_HD float speed_squared(const float u[3]) { return u[0] * u[0] + u[1] * u[1] + u[2] * u[2]; }
SHIP_LRM_HD float equilibrium(int i, float rho, const float u[3]) {
  const EvenOddParts e = equilibrium_parts(i, rho, u, speed_squared(u));
  return e.even + e.odd;
}

// Zeroth and first moments, thesis eqs. 6.11 and 6.12: rho and momentum j = sum c_i f_i.
// By pairs of opposite directions (d3q19.hpp): c_i f_i + c_o f_o = c_i (f_i - f_o).
SHIP_LRM_HD void moments(const float g[Q], float& rho, float j[3]) {
  float drho = g[0], jx = 0.0f, jy = 0.0f, jz = 0.0f;
  SHIP_LRM_UNROLL
  for (int i = 1; i <= 9; ++i) {
    const int o = d3q19::opp(i);
    drho += g[i] + g[o];
    const float d = g[i] - g[o];
    add_times(jx, d3q19::cx(i), d);
    add_times(jy, d3q19::cy(i), d);
    add_times(jz, d3q19::cz(i), d);
  }
  rho = 1.0f + drho;
  j[0] = jx;
  j[1] = jy;
  j[2] = jz;
}

// Macroscopic state including the Guo half-force shift u = (j + F/2) / rho (Guo, Zheng & Shi
// 2002, Phys. Rev. E 65, 046308, eq. 20; thesis 6.1.2 "u* = u + 0.5 dt F").
SHIP_LRM_HD Macro macro_from_moments(float rho, const float j[3], const float force[3]) {
  Macro m;
  m.rho = rho;
  const float inv = 1.0f / rho;
  for (int a = 0; a < 3; ++a) m.u[a] = (j[a] + 0.5f * force[a]) * inv;
  return m;
}
SHIP_LRM_HD Macro macro_from_populations(const float g[Q], const float force[3]) {
  float rho, j[3];
  moments(g, rho, j);
  return macro_from_moments(rho, j, force);
}

// Fictitious forces of a non-inertial frame (the LRM domain fixed to the rotorcraft; docs/design.md
// "The domain moves with the rotorcraft"). Per unit mass, with r from the frame's reference point (Landau & Lifshitz,
// Mechanics, 3rd ed., section 39, eq. 39.7):
//   a = -a_O - dOmega/dt x r - Omega x (Omega x r) - 2 Omega x u.
// The terms without u are affine in the cell position p: a(p) = accel + gradient p (gradient row-major),
// so a kernel needs 15 numbers; the Coriolis term uses the momentum j = rho u of the populations
// (explicit; its error is of order (|Omega| dt)^2, 1e-6 for a helicopter's rates).
struct FrameForce {
  float accel[3] = {0, 0, 0};
  float gradient[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
  float omega[3] = {0, 0, 0};
};

// Adds the fictitious force density of `fr` at cell position p to F (lattice units).
SHIP_LRM_HD void add_frame_force(const FrameForce& fr, const float p[3], float rho, const float j[3], float F[3]) {
  const float* m = fr.gradient;
  const float* w = fr.omega;
  F[0] += rho * (fr.accel[0] + m[0] * p[0] + m[1] * p[1] + m[2] * p[2]) - 2.0f * (w[1] * j[2] - w[2] * j[1]);
  F[1] += rho * (fr.accel[1] + m[3] * p[0] + m[4] * p[1] + m[5] * p[2]) - 2.0f * (w[2] * j[0] - w[0] * j[2]);
  F[2] += rho * (fr.accel[2] + m[6] * p[0] + m[7] * p[1] + m[8] * p[2]) - 2.0f * (w[0] * j[1] - w[1] * j[0]);
}

// Non-equilibrium momentum flux Pi_ab = sum c_a c_b (f - f_eq) (thesis eq. 6.13) as xx yy zz xy xz yz.
// c_a c_b is the same for a direction and its opposite, so the pairs' sums enter (directions 1 - 9
// and their opposites 10 - 18, d3q19.hpp); the rest direction has c = 0.
SHIP_LRM_HD void pi_neq(const float g[Q], const Macro& m, float p[6]) {
  for (int k = 0; k < 6; ++k) p[k] = 0.0f;
  const float uu = speed_squared(m.u);
  SHIP_LRM_UNROLL
  for (int i = 1; i <= 9; ++i) {
    const float ne = (g[i] + g[d3q19::opp(i)]) - 2.0f * equilibrium_parts(i, m.rho, m.u, uu).even;
    const int x = d3q19::cx(i), y = d3q19::cy(i), z = d3q19::cz(i);
    add_times(p[0], x * x, ne);
    add_times(p[1], y * y, ne);
    add_times(p[2], z * z, ne);
    add_times(p[3], x * y, ne);
    add_times(p[4], x * z, ne);
    add_times(p[5], y * z, ne);
  }
}
// Its norm sqrt(Pi:Pi).
SHIP_LRM_HD float tensor_norm(const float p[6]) {
  return sqrtf(p[0] * p[0] + p[1] * p[1] + p[2] * p[2] + 2.0f * (p[3] * p[3] + p[4] * p[4] + p[5] * p[5]));
}
SHIP_LRM_HD float pi_neq_norm(const float g[Q], const Macro& m) {
  float p[6];
  pi_neq(g, m, p);
  return tensor_norm(p);
}

// Relaxation frequency with the Smagorinsky sub-grid model (thesis 6.1.2, equations after 6.13):
//   S = (sqrt(nu^2 + 18 s^2 |Pi|) - nu) / (6 s^2),  omega = 1 / (3 (nu + s^2 S) + 1/2),
// with |Pi| taken per unit density (Hou et al. 1996, J. Comput. Phys. 118, 329).
SHIP_LRM_HD float smagorinsky_omega(float nu, float s, float pi_norm_per_rho) {
  const float s2 = s * s;
  const float S = (sqrtf(nu * nu + 18.0f * s2 * pi_norm_per_rho) - nu) / (6.0f * s2);
  return 1.0f / (3.0f * (nu + s2 * S) + 0.5f);
}

// Guo et al. 2002 eq. 20, the forcing term of direction i: (1 - omega/2) w_i [ (c_i - u)/cs^2 +
// (c_i.u) c_i / cs^4 ] . F, as its parts even and odd in c_i (as equilibrium_parts):
// guo w_i (9 (c_i.u)(c_i.F) - 3 u.F) and guo w_i 3 c_i.F, with guo = 1 - omega/2 and uF = u.F.
SHIP_LRM_HD EvenOddParts guo_source_parts(int i, const float u[3], const float F[3], float uF, float guo) {
  const float gw = guo * d3q19::w(i);
  if (i == 0) return {gw * (-3.0f * uF), 0.0f};
  const float cu = lattice_dot(i, u), cF = lattice_dot(i, F);
  return {gw * (9.0f * cu * cF - 3.0f * uF), gw * (3.0f * cF)};
}

// BGK collision (thesis eq. 6.9) with Smagorinsky (kSmagorinsky, s = p.smagorinsky) and Guo
// forcing (force density F per unit volume, lattice units) about the state m that enters the
// equilibrium (with the Guo half-force shift when forced). Overwrites g with the post-collision
// populations. The model choice is a template parameter so that the bulk loop has no branches and
// vectorises.
template <bool kSmagorinsky, bool kForced = true>
SHIP_LRM_HD void relax(float g[Q], const Macro& m, const float force[3], const CollisionParams& p) {
  const float omega = kSmagorinsky ? smagorinsky_omega(p.nu, p.smagorinsky, pi_neq_norm(g, m) / m.rho) : omega_from_nu(p.nu);
  const float guo = 1.0f - 0.5f * omega;
  const float uF = m.u[0] * force[0] + m.u[1] * force[1] + m.u[2] * force[2];
  const float uu = speed_squared(m.u);
  // (unforced, no source is added: x + 0.0f is not folded away under IEEE rules)
  const float r0 = omega * (equilibrium_parts(0, m.rho, m.u, uu).even - g[0]);
  g[0] += kForced ? r0 + guo_source_parts(0, m.u, force, uF, guo).even : r0;
  SHIP_LRM_UNROLL
  for (int i = 1; i <= 9; ++i) {
    const int o = d3q19::opp(i);
    const EvenOddParts e = equilibrium_parts(i, m.rho, m.u, uu);
    const float ri = omega * ((e.even + e.odd) - g[i]), ro = omega * ((e.even - e.odd) - g[o]);
    if (kForced) {
      const EvenOddParts s = guo_source_parts(i, m.u, force, uF, guo);
      g[i] += ri + (s.even + s.odd);
      g[o] += ro + (s.even - s.odd);
    } else {
      g[i] += ri;
      g[o] += ro;
    }
  }
}

// Recursive regularised collision (Malaspinas 2015, "Increasing stability and accuracy of the lattice
// Boltzmann scheme: recursivity and regularization", arXiv:1505.06900; for D3Q19 Coreixas et al. 2017,
// Phys. Rev. E 96, 033306, section IV and appendix). Post-collision populations
//   f_i = f_eq,i + (1 - omega) f_neq,i + 1/2 F_i
// with f_neq rebuilt from Hermite moments instead of taken from f:
//   f_neq,i = w_i [ H2_i : a2 / (2 cs^4) + third-order part ],
// a2 = Pi_neq + (u F + F u) / 2 (the Guo shift: f - f_eq + F_i / 2 is the non-equilibrium part that
// relaxes, Krueger et al. 2017, The Lattice Boltzmann Method, section 6.3), and its third-order
// moments from the recursion a3_abc = u_a a2_bc + u_b a2_ac + u_c a2_ab. The equilibrium adds the
// third-order Hermite terms with a3_eq = rho u_a u_b u_c. D3Q19 holds, per odd axis b and the other two
// axes a1, a2, the polynomials P+ = H_a1a1b + H_a2a2b = c_b (c_a1^2 + c_a2^2 - 2/3) and
// P- = H_a1a1b - H_a2a2b = c_b (c_a1^2 - c_a2^2), orthogonal in the w-weighted sum with norms 2/27 and
// 6/27, so their terms are w_i P_i A / norm with A the moment sum_i P_i f_i (27/2 and 27/6 below).
// Mass, momentum and Pi relax as in BGK (same viscosity); the moments BGK leaves undamped near
// tau = 1/2 (the ghosts) are set to their equilibrium, the third-order ones follow a2.
// Smagorinsky takes |Pi_neq| as in relax<>. The Guo source enters at half weight (guo_source_parts
// with 1/2), as the rewritten BGK with forcing does.
template <bool kSmagorinsky, bool kForced = true>
SHIP_LRM_HD void relax_recursive(float g[Q], const Macro& m, const float force[3], const CollisionParams& p) {
  float a2[6];
  pi_neq(g, m, a2);
  const float omega = kSmagorinsky ? smagorinsky_omega(p.nu, p.smagorinsky, tensor_norm(a2) / m.rho) : omega_from_nu(p.nu);
  const float* u = m.u;
  if (kForced) {
    const float* F = force;
    a2[0] += u[0] * F[0];
    a2[1] += u[1] * F[1];
    a2[2] += u[2] * F[2];
    a2[3] += 0.5f * (u[0] * F[1] + u[1] * F[0]);
    a2[4] += 0.5f * (u[0] * F[2] + u[2] * F[0]);
    a2[5] += 0.5f * (u[1] * F[2] + u[2] * F[1]);
  }
  const float keep = 1.0f - omega;
  const float a2t[3][3] = {{a2[0], a2[3], a2[4]}, {a2[3], a2[1], a2[5]}, {a2[4], a2[5], a2[2]}};
  // t(a, b) = a3_aab of the post-collision populations: rho u_a^2 u_b + keep (2 u_a a2_ab + u_b a2_aa)
  auto t = [&](int a, int b) { return m.rho * u[a] * u[a] * u[b] + keep * (2.0f * u[a] * a2t[a][b] + u[b] * a2t[a][a]); };
  float plus[3], minus[3];  // per odd axis b: the coefficients 27/2 A+ and 27/6 A-
  for (int b = 0; b < 3; ++b) {
    const float t1 = t((b + 1) % 3, b), t2 = t((b + 2) % 3, b);
    plus[b] = 13.5f * (t1 + t2);
    minus[b] = 4.5f * (t1 - t2);
  }
  const float uF = u[0] * force[0] + u[1] * force[1] + u[2] * force[2];
  const float uu = speed_squared(u);
  const float trace = a2[0] + a2[1] + a2[2];
  // rest direction: H2_0 : a2 = -tr(a2) / 3, no odd part
  const float n0 = equilibrium_parts(0, m.rho, u, uu).even - keep * (4.5f / 3.0f) * d3q19::w(0) * trace;
  g[0] = kForced ? n0 + guo_source_parts(0, u, force, uF, 0.5f).even : n0;
  SHIP_LRM_UNROLL
  for (int i = 1; i <= 9; ++i) {
    const int o = d3q19::opp(i);
    const int c[3] = {d3q19::cx(i), d3q19::cy(i), d3q19::cz(i)};
    const EvenOddParts e = equilibrium_parts(i, m.rho, u, uu);
    // H2_i : a2 = c.a2.c - tr(a2) / 3
    float h2 = -trace / 3.0f;
    add_times(h2, c[0] * c[0], a2[0]);
    add_times(h2, c[1] * c[1], a2[1]);
    add_times(h2, c[2] * c[2], a2[2]);
    add_times(h2, 2 * c[0] * c[1], a2[3]);
    add_times(h2, 2 * c[0] * c[2], a2[4]);
    add_times(h2, 2 * c[1] * c[2], a2[5]);
    float h3 = 0.0f;  // sum over b of P+ plus_b + P- minus_b (each c_b known at compile time)
    for (int b = 0; b < 3; ++b) {
      if (c[b] == 0) continue;
      const int s1 = c[(b + 1) % 3] * c[(b + 1) % 3], s2 = c[(b + 2) % 3] * c[(b + 2) % 3];
      const float term = (static_cast<float>(s1 + s2) - 2.0f / 3.0f) * plus[b] + static_cast<float>(s1 - s2) * minus[b];
      h3 = c[b] > 0 ? h3 + term : h3 - term;
    }
    const float w = d3q19::w(i);
    float even = e.even + keep * 4.5f * w * h2, odd = e.odd + w * h3;
    if (kForced) {
      const EvenOddParts s = guo_source_parts(i, u, force, uF, 0.5f);
      even += s.even;
      odd += s.odd;
    }
    g[i] = even + odd;
    g[o] = even - odd;
  }
}

// The collision of kind kCollision (collision_kind).
template <int kCollision, bool kForced = true>
SHIP_LRM_HD void collide(float g[Q], const Macro& m, const float force[3], const CollisionParams& p) {
  constexpr bool kSmagorinsky = (kCollision & kSmagorinskyBit) != 0;
  if constexpr ((kCollision & kRecursiveBit) != 0)
    relax_recursive<kSmagorinsky, kForced>(g, m, force, p);
  else
    relax<kSmagorinsky, kForced>(g, m, force, p);
}
// With the model chosen at run time (cells off the vectorised bulk path).
SHIP_LRM_HD void collide(float g[Q], const Macro& m, const float force[3], const CollisionParams& p) {
  switch (collision_kind(p)) {
    case 0:
      return collide<0>(g, m, force, p);
    case 1:
      return collide<1>(g, m, force, p);
    case 2:
      return collide<2>(g, m, force, p);
    default:
      return collide<3>(g, m, force, p);
  }
}

// ---- Open boundaries (thesis 6.1.3) ---------------------------------------------------------
// A boundary cell has one outward normal axis `axis` with sign `sgn` (+1 or -1). Populations
// with c.n < 0 come from outside and are unknown; those with c.n > 0 leave the domain.

// K = sum_{c.n=0} f + 2 sum_{c.n>0} f, so that rho (1 + u.n) = K (Zou & He 1997, Phys. Fluids 9,
// 1591; thesis "rho^Wall = (2 rho^+ + rho^0) / (1 + u_n)").
SHIP_LRM_HD float zou_he_known_sum(const float g[Q], int axis, int sgn) {
  float k = 1.0f;  // sum of the shifted weights of these populations is exactly 1
  SHIP_LRM_UNROLL
  for (int i = 0; i < Q; ++i) {
    const int cn = d3q19::c(i, axis) * sgn;
    add_times(k, cn == 0 ? 1 : (cn > 0 ? 2 : 0), g[i]);
  }
  return k;
}

// Tangential momentum at an outlet from the known populations, mirroring the outgoing ones onto
// the unknown ones as the density formula does: j_t = sum_{c.n=0} c_t f + 2 sum_{c.n>0} c_t f.
SHIP_LRM_HD float zou_he_tangential_momentum(const float g[Q], int axis, int sgn, int t) {
  float j = 0.0f;
  SHIP_LRM_UNROLL
  for (int i = 0; i < Q; ++i) {
    const int cn = d3q19::c(i, axis) * sgn;
    add_times(j, (cn == 0 ? 1 : (cn > 0 ? 2 : 0)) * d3q19::c(i, t), g[i]);
  }
  return j;
}

// Reconstruction of all populations from rho, u and the strain rate S = (grad u + grad u^T)/2
// (Latt, Chopard, Malaspinas, Deville & Michler 2008, Phys. Rev. E 77, 056703, "FD" scheme;
// thesis: g_i = f_eq(rho,u) - rho w_i / (cs^2 omega) Q_i : S, Q_i = c_i c_i - cs^2 I).
// S is given as xx yy zz xy xz yz.
SHIP_LRM_HD void reconstruct_fd(float g[Q], float rho, const float u[3], const float S[6], float omega) {
  SHIP_LRM_UNROLL
  for (int i = 0; i < Q; ++i) {
    const int x = d3q19::cx(i), y = d3q19::cy(i), z = d3q19::cz(i);
    float shear = 0.0f;  // x y S_xy + x z S_xz + y z S_yz
    add_times(shear, x * y, S[3]);
    add_times(shear, x * z, S[4]);
    add_times(shear, y * z, S[5]);
    const float qs = (x * x - d3q19::cs2) * S[0] + (y * y - d3q19::cs2) * S[1] + (z * z - d3q19::cs2) * S[2] + 2.0f * shear;
    g[i] = equilibrium(i, rho, u) - 3.0f * rho * d3q19::w(i) / omega * qs;
  }
}

// Non-reflecting impedance outlet, thesis eq. 6.15 (after Friedmann's impedance boundary):
// the change of density and outward normal velocity over one step must satisfy
//   cs^2 d(rho) + 1/2 rho d(u_n)^2 - rho cs d(u_n) = 0,
// i.e. only an outgoing acoustic wave (p' = rho cs u') is admitted, together with the Zou-He
// relation rho (1 + u_n) = K. With a = 1 + un_prev, rho du_n = K - a rho, so rho times the condition is
// a quadratic in rho,
//   (cs^2 + a^2/2 + cs a) rho^2 - (cs^2 rho_prev + K a + cs K) rho + K^2/2 = 0,
// solved in closed form (one square root instead of Newton iterations). Its roots have the product
// K^2 / (2 A); when nothing changes (K = a rho_prev) rho_prev is the larger one and the other is about
// 0.35 rho_prev (|du_n| near the speed of sound), so the larger root is the physical one. In a moving
// domain the undisturbed flow itself changes; d(u_n) is then taken relative to it (un_prev includes
// the reference's change), so that only the disturbance radiates and the mean flow keeps its density.
// rho_prev: the previous density, or, for a partially non-reflecting outlet, that density moved
// towards the reference by the relaxation (FaceCondition::pressure_relaxation).
SHIP_LRM_HD float impedance_density(float K, float rho_prev, float un_prev) {
  const float cs = d3q19::cs;
  const float a = 1.0f + un_prev;
  const float A = d3q19::cs2 + 0.5f * a * a + cs * a;
  const float B = d3q19::cs2 * rho_prev + K * a + cs * K;  // minus the linear coefficient
  const float disc = B * B - 2.0f * A * K * K;
  return (B + sqrtf(disc > 0.0f ? disc : 0.0f)) / (2.0f * A);
}

// Characteristic (non-reflecting) velocity inlet (FaceCondition::characteristic_inlet; Thompson 1987,
// J. Comput. Phys. 68, 1; for LBM Izquierdo & Fueyo 2008, Phys. Rev. E 78, 046707): the prescribed
// outward normal velocity un fixes the wave that enters, and the acoustic wave that leaves passes with
// p' = rho c_s u', so the outward normal velocity is un + c_s (rho - 1) / rho. With the Zou-He relation
// K = rho (1 + that velocity), rho = (K + c_s) / (1 + un + c_s). Returns rho; the cell's outward normal
// velocity is then characteristic_inlet_velocity(un, rho).
SHIP_LRM_HD float characteristic_inlet_density(float K, float un) { return (K + d3q19::cs) / (1.0f + un + d3q19::cs); }
SHIP_LRM_HD float characteristic_inlet_velocity(float un, float rho) { return un + d3q19::cs * (rho - 1.0f) / rho; }

}  // namespace ship_lrm::lbm
