// The device-copyable view of a lattice and the per-cell streaming, boundary and update
// operations shared by the CPU and CUDA backends (one source of physics).
//
// Streaming: in-place AA pattern (Bailey, Myre, Walsh, Lilja & Saar 2009, "Accelerating lattice
// Boltzmann fluid flow simulations using graphics processors", ICPP) with a single population
// array; the thesis (6.1.2) uses the related shift-and-swap scheme. With G[i][x] the stored value:
//   even step at x: read G[i][x], collide, write G[opp(i)][x]          (no neighbour access)
//   odd step at x:  read G[opp(i)][x - c_i], collide, write G[i][x + c_i]
// Each cell owns disjoint memory in both steps, so cells update in any order, in parallel.
// Walls use halfway bounce-back applied during the odd step's read and write (Ladd 1994,
// J. Fluid Mech. 271, 285; moving wall term 2 w_i rho_w c_i.u_w / cs^2 of Ladd's eq. 3.2).
#pragma once

#include <cstddef>
#include <cstdint>

#include "ship_lrm/lbm/cell_ops.hpp"
#include "ship_lrm/lbm/cell_types.hpp"

// Diagnostics build only (CMake -DSHIP_LRM_TRACE_CELL=x,y,z, as scripts/pack_gpu_binaries.sh with
// TRACE_CELL=x,y,z: defines SHIP_LRM_TRACE_X, _Y and _Z): pass 1 of the open boundaries prints its
// inputs and result at that cell on either backend, so that the CUDA backend's state there can be compared with the CPU's line by line
// (the LRM domain's open defect, docs/benchmarks.md at 193c1b4, the H200 figures). Nothing otherwise.
#ifdef SHIP_LRM_TRACE_X
#include <cstdio>
#ifdef __CUDA_ARCH__
#define SHIP_LRM_TRACE_BACKEND "cuda"
#else
#define SHIP_LRM_TRACE_BACKEND "cpu"
#endif
#define SHIP_LRM_TRACE_STATE(x, y, z, what, m)                                                                                   \
  do {                                                                                                                          \
    const int trace_at_[3] = {SHIP_LRM_TRACE_X, SHIP_LRM_TRACE_Y, SHIP_LRM_TRACE_Z};                                            \
    if ((x) == trace_at_[0] && (y) == trace_at_[1] && (z) == trace_at_[2])                                                      \
      printf("trace %s odd %d (%d, %d, %d) %s: rho %.9g u %.9g %.9g %.9g\n", SHIP_LRM_TRACE_BACKEND, kOdd ? 1 : 0, (x), (y), (z), \
             (what), (m).rho, (m).u[0], (m).u[1], (m).u[2]);                                                                    \
  } while (0)
#else
#define SHIP_LRM_TRACE_STATE(x, y, z, what, m) \
  do {                                         \
  } while (0)
#endif

namespace ship_lrm::lbm {

struct LatticeView {
  int n[3] = {0, 0, 0};
  std::size_t ncells = 0;
  std::size_t pstride = 0;             // distance between the arrays of two directions (>= ncells)
  pop_t* g = nullptr;                  // Q * pstride, SoA: g[i * pstride + cell]
  const std::uint8_t* type = nullptr;  // CellType, with kGeneralBit on checked fluid cells
  const std::uint8_t* tag = nullptr;   // fluid: reflection rule (see reflect); moving wall: index
  const float* force = nullptr;        // optional force density field, SoA 3 * ncells
  float uniform_force[3] = {0, 0, 0};
  bool frame_active = false;  // add the fictitious forces of `frame` (non-inertial domain)
  FrameForce frame;
  std::uint8_t face[6] = {0, 0, 0, 0, 0, 0};                   // FaceType per face
  float face_velocity[6][3] = {};                              // wall velocity of MovingWall faces
  std::uint8_t face_inflow_reference[6] = {0, 0, 0, 0, 0, 0};  // FaceCondition::inflow_from_reference
  float face_pressure_relaxation[6] = {};                      // FaceCondition::pressure_relaxation
  std::uint8_t face_total_pressure[6] = {0, 0, 0, 0, 0, 0};    // FaceCondition::total_pressure_inflow
  std::uint8_t face_characteristic[6] = {0, 0, 0, 0, 0, 0};    // FaceCondition::characteristic_inlet
  const WallMotion* walls = nullptr;
  CollisionParams params;
  // Open boundary cells (thesis 6.1.3), numbered b = 0 .. nbnd-1.
  int nbnd = 0;
  const std::uint32_t* bnd_cell = nullptr;   // cell index of b
  const std::uint8_t* bnd_normal = nullptr;  // outward normal code axis*2 + (sign > 0)
  const std::uint32_t* bnd_mask = nullptr;   // link mask of b (see gather_masked)
  const float* bnd_value =
      nullptr;           // 4 * nbnd: inlet velocity (3) | outlet density ([0]) | impedance: reference velocity (3), its normal change ([3])
  float* aux = nullptr;  // state (rho, u) of the open boundaries' support cells, SoA 4 * ncells
  const std::int64_t* row_offsets = nullptr;  // 27 * Q neighbour offsets of bulk cells per cell class
  // Velocity-gradient stencil of each open-boundary cell (gradient_stencil; Lattice::finalize):
  // 9 cells and 9 weights per cell, 3 per axis.
  const std::uint32_t* bnd_grad_cell = nullptr;
  const float* bnd_grad_weight = nullptr;
  // Held cells (Lattice::set_held), numbered h = 0 .. nheld-1: cell and wall index.
  int nheld = 0;
  const std::uint32_t* held_cell = nullptr;
  const std::uint8_t* held_wall = nullptr;
  // Cells of the absorbing layers (FaceCondition::absorbing_cells; Lattice::absorbing_cells),
  // numbered a = 0 .. nabsorbing-1: cell, the boundary index of the face cell whose velocity is its
  // target, and the strength sigma per step.
  int nabsorbing = 0;
  const std::uint32_t* absorbing_cell = nullptr;
  const std::uint32_t* absorbing_target = nullptr;
  const float* absorbing_sigma = nullptr;
};

// Class of a bulk cell: x, y and z each first (0), interior (1) or last (2); cells on a periodic
// face reach their neighbours by wrapped offsets that are the same for the whole class.
SHIP_LRM_HD int cell_class(const int n[3], int x, int y, int z) {
  return 9 * (x == 0 ? 0 : (x == n[0] - 1 ? 2 : 1)) + 3 * (y == 0 ? 0 : (y == n[1] - 1 ? 2 : 1)) + (z == 0 ? 0 : (z == n[2] - 1 ? 2 : 1));
}

SHIP_LRM_HD std::size_t cell_index(const LatticeView& v, int x, int y, int z) {
  return static_cast<std::size_t>(x) +
         static_cast<std::size_t>(v.n[0]) * (static_cast<std::size_t>(y) + static_cast<std::size_t>(v.n[1]) * z);
}
SHIP_LRM_HD pop_t& pop(const LatticeView& v, int i, std::size_t cell) { return v.g[static_cast<std::size_t>(i) * v.pstride + cell]; }

// Stride between the population arrays of two directions: the cell count rounded up to 4 KiB and
// shifted by 5 cache lines per direction, so that the 38 streams of a step fall into different
// cache sets (with a power-of-two lattice they would all alias one set and thrash the L1).
inline std::size_t population_stride(std::size_t ncells) {
  const std::size_t page = 4096 / sizeof(pop_t), shift = 5 * 64 / sizeof(pop_t);
  return (ncells + page - 1) / page * page + shift;
}

// Force on a cell: none, the uniform force only, uniform plus the per-cell field, or the fictitious
// forces of a non-inertial frame (which depend on the cell's state) plus the uniform force, without
// or with the field. The mode is a template parameter of the updates, so that whether they read the
// field is known when they are compiled: a test of the field pointer per cell is control flow that
// GCC does not vectorise, and made the frame's step (the LRM domain decelerating) 3.7 times slower
// than the others on the CPU (docs/benchmarks.md at 193c1b4, 2026-12-03).
enum ForceMode : int { kNoForce = 0, kUniformForce = 1, kForceField = 2, kFrameForce = 3, kFrameForceField = 4 };
SHIP_LRM_HD constexpr bool has_force_field(int mode) { return mode == kForceField || mode == kFrameForceField; }
SHIP_LRM_HD constexpr bool has_frame_force(int mode) { return mode == kFrameForce || mode == kFrameForceField; }

// Coordinates of cell c. In 32-bit arithmetic where the index fits (every lattice here): a 64-bit
// division costs several times a 32-bit one on x86 and GPUs, and the boundary passes call this per
// cell and step.
SHIP_LRM_HD void cell_coords(const LatticeView& v, std::size_t c, int& x, int& y, int& z) {
  if (c <= 0xffffffffu) {
    const auto c32 = static_cast<std::uint32_t>(c), nx = static_cast<std::uint32_t>(v.n[0]), ny = static_cast<std::uint32_t>(v.n[1]);
    const std::uint32_t r = c32 / nx;
    x = static_cast<int>(c32 - r * nx);
    y = static_cast<int>(r % ny);
    z = static_cast<int>(r / ny);
    return;
  }
  x = static_cast<int>(c % v.n[0]);
  const std::size_t r = c / v.n[0];
  y = static_cast<int>(r % v.n[1]);
  z = static_cast<int>(r / v.n[1]);
}

// Force density on cell c before the frame's fictitious forces: the uniform force and the field.
template <int kForce>
SHIP_LRM_HD void base_force(const LatticeView& v, std::size_t c, float F[3]) {
  for (int a = 0; a < 3; ++a)
    F[a] = (kForce == kNoForce ? 0.0f : v.uniform_force[a]) + (has_force_field(kForce) ? v.force[a * v.ncells + c] : 0.0f);
}

// The state (density, velocity with the Guo half-force shift) that enters a cell's collision, from
// its pre-collision populations g; F holds its base_force and is completed with the frame's
// fictitious forces at the cell's position p (used in the frame's modes only). The moments are summed
// once, since the fictitious forces need them too.
template <int kForce>
SHIP_LRM_HD Macro collision_state(const LatticeView& v, const float p[3], const float g[Q], float F[3]) {
  float rho, j[3];
  moments(g, rho, j);
  if (has_frame_force(kForce)) add_frame_force(v.frame, p, rho, j, F);
  return macro_from_moments(rho, j, F);
}

// Position of cell c in lattice units (the frame's fictitious forces depend on it).
SHIP_LRM_HD void cell_position(const LatticeView& v, std::size_t c, float p[3]) {
  int x, y, z;
  cell_coords(v, c, x, y, z);
  p[0] = static_cast<float>(x);
  p[1] = static_cast<float>(y);
  p[2] = static_cast<float>(z);
}

// Force density F on cell c at position p and the state that enters its collision
// (collision_state). The bulk passes know p without dividing the index (a 32-bit integer division
// per cell does not vectorise on x86 and made a step with the frame's forces twice as slow).
template <int kForce>
SHIP_LRM_HD Macro cell_state(const LatticeView& v, std::size_t c, const float p[3], const float g[Q], float F[3]) {
  base_force<kForce>(v, c, F);
  return collision_state<kForce>(v, p, g, F);
}
// The same with the position looked up (only the frame's forces need it).
template <int kForce>
SHIP_LRM_HD Macro cell_state(const LatticeView& v, std::size_t c, const float g[Q], float F[3]) {
  float p[3] = {0.0f, 0.0f, 0.0f};
  if (has_frame_force(kForce)) cell_position(v, c, p);
  return cell_state<kForce>(v, c, p, g, F);
}
SHIP_LRM_HD bool uniform_force_set(const LatticeView& v) {
  return v.uniform_force[0] != 0.0f || v.uniform_force[1] != 0.0f || v.uniform_force[2] != 0.0f;
}
SHIP_LRM_HD int force_mode(const LatticeView& v) {
  if (v.frame_active) return v.force ? kFrameForceField : kFrameForce;
  return v.force ? kForceField : (uniform_force_set(v) ? kUniformForce : kNoForce);
}
// The same with the mode chosen at run time (cells off the vectorised bulk path).
SHIP_LRM_HD Macro cell_state(const LatticeView& v, std::size_t c, const float g[Q], float F[3]) {
  switch (force_mode(v)) {
    case kNoForce:
      return cell_state<kNoForce>(v, c, g, F);
    case kUniformForce:
      return cell_state<kUniformForce>(v, c, g, F);
    case kForceField:
      return cell_state<kForceField>(v, c, g, F);
    case kFrameForce:
      return cell_state<kFrameForce>(v, c, g, F);
    default:
      return cell_state<kFrameForceField>(v, c, g, F);
  }
}

// Is cell nb (the neighbour of (x,y,z) at d) fluid-like? If it is a wall, uw is its velocity at the
// link's midpoint (zero for a resting wall).
SHIP_LRM_HD bool fluid_or_wall(const LatticeView& v, std::size_t nb, int x, int y, int z, int dx, int dy, int dz, float uw[4]) {
  uw[0] = uw[1] = uw[2] = uw[3] = 0.0f;
  const auto t = static_cast<CellType>(v.type[nb] & ~kGeneralBit);
  if (!is_wall(t)) return true;
  if (t == CellType::MovingWall) {
    const WallMotion& m = v.walls[v.tag[nb]];
    rigid_velocity(m, x + 0.5f * dx, y + 0.5f * dy, z + 0.5f * dz, uw);
    uw[3] = m.local_density;
  }
  return false;
}

// What lies at (x,y,z) + d: a fluid-like cell (returns true and its index nb) or a wall or the
// outside of a non-periodic face (returns false and the wall velocity uw at the link midpoint).
SHIP_LRM_HD bool neighbour(const LatticeView& v, int x, int y, int z, int dx, int dy, int dz, std::size_t& nb, float uw[4]) {
  int p[3] = {x + dx, y + dy, z + dz};
  bool outside = false;
  uw[0] = uw[1] = uw[2] = uw[3] = 0.0f;
  SHIP_LRM_UNROLL  // constant indices: p stays in registers (component() in hd.hpp)
  for (int a = 0; a < 3; ++a) {
    if (p[a] >= 0 && p[a] < v.n[a]) continue;
    const int f = 2 * a + (p[a] >= v.n[a] ? 1 : 0);
    if (static_cast<FaceType>(v.face[f]) == FaceType::Periodic) {
      p[a] = (p[a] + v.n[a]) % v.n[a];
      continue;
    }
    outside = true;
    if (static_cast<FaceType>(v.face[f]) == FaceType::MovingWall)
      for (int k = 0; k < 3; ++k) uw[k] = v.face_velocity[f][k];
  }
  if (outside) return false;
  nb = static_cast<std::size_t>(p[0]) +
       static_cast<std::size_t>(v.n[0]) * (static_cast<std::size_t>(p[1]) + static_cast<std::size_t>(v.n[1]) * p[2]);
  return fluid_or_wall(v, nb, x, y, z, dx, dy, dz, uw);
}

// Offsets of the neighbours of (x,y,z) if it lies on no face of the domain, else nullptr.
SHIP_LRM_HD const std::int64_t* inner_offsets(const LatticeView& v, int x, int y, int z) {
  return cell_class(v.n, x, y, z) == 13 ? v.row_offsets + Q * 13 : nullptr;
}

// neighbour() for direction i (+1) or its opposite (-1): through the fixed offsets `inner` of a
// cell on no face when given (the same answer without the search), else by the search.
SHIP_LRM_HD bool neighbour_along(const LatticeView& v, int x, int y, int z, std::size_t c, const std::int64_t* inner, int i, int sign,
                                 std::size_t& nb, float uw[4]) {
  const int dx = sign * d3q19::cx(i), dy = sign * d3q19::cy(i), dz = sign * d3q19::cz(i);
  if (!inner) return neighbour(v, x, y, z, dx, dy, dz, nb, uw);
  nb = c + inner[sign > 0 ? i : d3q19::opp(i)];
  return fluid_or_wall(v, nb, x, y, z, dx, dy, dz, uw);
}

// Direction into which a population leaving cell c with direction i towards a wall returns to c.
// The cell's tag (set by Lattice::finalize) is its rule: the set of complete slip-wall planes it
// touches, bit 2a + (s > 0) for the plane on side s of axis a; 0 = none: every wall link bounces back
// (reverse c_i, no-slip). A link that crosses a slip plane (c_a = s) and has no component along
// the axis of any other of the cell's slip planes reflects specularly (reverse component a); every
// other wall link bounces back. In a plane wall that is specular reflection for every link. In the
// edge where two slip planes meet, every link with a component along the edge (the links that
// carry the edge-wise momentum) crosses one plane only and reflects specularly, so the edge is
// free-slip too; the links across the edge (no component along it) bounce back, which reverses them
// just as the two specular reflections of the exact edge would. Before, such a cell reflected at one
// plane only and bounced the links through the other back: a no-slip line along every slip edge,
// and where it met a velocity inlet a singular corner, one of the two causes of the wake
// precompute's noisy inlet (docs/design.md, "Slip edges"). Both kinds map the directions that hit walls one-to-one onto the
// directions that come back (a mirrored image has no component along the other slip axes, a
// bounced one has, unless it crosses no slip plane at all), so every population slot keeps exactly
// one writer (AA pattern) and mass is conserved. With arriving = true the inverse map is returned:
// the outgoing direction that comes back as i.
SHIP_LRM_HD int reflect_by_rule(int planes, int i, bool arriving) {
  if (planes == 0) return d3q19::opp(i);
  const int j = arriving ? d3q19::opp(i) : i;  // the link towards the wall
  for (int a = 0; a < 3; ++a) {
    const int s = d3q19::c(j, a);
    if (s == 0 || !((planes >> (2 * a + (s > 0 ? 1 : 0))) & 1)) continue;
    bool alone = true;  // no component along another slip plane's axis
    for (int b = 0; b < 3; ++b)
      if (b != a && d3q19::c(j, b) != 0 && ((planes >> (2 * b)) & 3)) alone = false;
    if (!alone) return d3q19::opp(i);
    return d3q19::index_of(a == 0 ? -d3q19::cx(i) : d3q19::cx(i), a == 1 ? -d3q19::cy(i) : d3q19::cy(i),
                           a == 2 ? -d3q19::cz(i) : d3q19::cz(i));
  }
  return d3q19::opp(i);
}
SHIP_LRM_HD int reflect(const LatticeView& v, std::size_t c, int i, bool arriving) { return reflect_by_rule(v.tag[c], i, arriving); }

// Moving-wall momentum term for the population arriving with direction d, per unit rho_w (the
// checked gather and scatter multiply it by rho_w, see WallMotion::local_density).
SHIP_LRM_HD float wall_term(int d, const float uw[3]) { return 6.0f * d3q19::w(d) * lattice_dot(d, uw); }

// Ladd's moving-wall terms (term[i] per unit rho_w, 0 on links that reach fluid; weight[i] the
// wall's local_density a) added to populations g (sign +1: gather) or taken off them (sign -1:
// emitted) with rho_w = 1 + a (rho - 1), rho the density the resulting populations make:
// rho - 1 = sum(g) + sign sum(term) + sign (rho - 1) sum(a term).
SHIP_LRM_HD void apply_wall_terms(float g[Q], const float term[Q], const float weight[Q], float sign) {
  float sum = g[0], local = 0.0f;
  for (int i = 1; i < Q; ++i) {
    local += weight[i] * term[i];
    sum += sign * term[i];
    sum += g[i];
  }
  const float drho = local != 0.0f ? sum / (1.0f - sign * local) : 0.0f;
  for (int i = 1; i < Q; ++i)
    if (term[i] != 0.0f) g[i] += sign * ((1.0f + weight[i] * drho) * term[i]);
}

// Pre-collision populations of cell (x,y,z) for the step of the given parity.
template <bool kOdd>
SHIP_LRM_HD void gather(const LatticeView& v, int x, int y, int z, std::size_t c, float g[Q]) {
  if (!kOdd) {
    SHIP_LRM_UNROLL
    for (int i = 0; i < Q; ++i) g[i] = load_pop(pop(v, i, c));
    return;
  }
  g[0] = load_pop(pop(v, 0, c));
  const std::int64_t* inner = inner_offsets(v, x, y, z);
  float term[Q], weight[Q];
  SHIP_LRM_UNROLL  // (the directions' components fold; cells next to moving walls were a fifth of a step over the deck)
  for (int i = 1; i < Q; ++i) {
    std::size_t nb;
    float uw[4];
    term[i] = weight[i] = 0.0f;
    if (neighbour_along(v, x, y, z, c, inner, i, -1, nb, uw)) {
      g[i] = load_pop(pop(v, d3q19::opp(i), nb));
    } else {
      // arriving from a wall: the outgoing population k (reflected onto i) stored by the even step
      const int k = reflect(v, c, i, true);
      g[i] = load_pop(pop(v, d3q19::opp(k), c));
      term[i] = wall_term(i, uw);
      weight[i] = uw[3];
    }
  }
  apply_wall_terms(g, term, weight, 1.0f);
}

// Store post-collision populations of cell (x,y,z) for the step of the given parity.
template <bool kOdd>
SHIP_LRM_HD void scatter(const LatticeView& v, int x, int y, int z, std::size_t c, const float g[Q]) {
  if (!kOdd) {
    SHIP_LRM_UNROLL
    for (int i = 0; i < Q; ++i) pop(v, d3q19::opp(i), c) = store_pop(g[i]);
    return;
  }
  pop(v, 0, c) = store_pop(g[0]);
  float drho = 0.0f;  // the cell's density - 1 (collision keeps the mass), for rho_w
  SHIP_LRM_UNROLL
  for (int i = 0; i < Q; ++i) drho += g[i];
  const std::int64_t* inner = inner_offsets(v, x, y, z);
  SHIP_LRM_UNROLL
  for (int i = 1; i < Q; ++i) {
    std::size_t nb;
    float uw[4];
    if (neighbour_along(v, x, y, z, c, inner, i, +1, nb, uw)) {
      pop(v, i, nb) = store_pop(g[i]);
    } else {
      const int k = reflect(v, c, i, false);  // comes back into this cell with direction k
      pop(v, k, c) = store_pop(g[i] + (1.0f + uw[3] * drho) * wall_term(k, uw));
    }
  }
}

// The post-collision populations cell (x,y,z) emitted in the step just done (its parity kOdd), read
// back from where scatter<kOdd> stored them, the moving-wall term taken off the reflected ones.
template <bool kOdd>
SHIP_LRM_HD void emitted(const LatticeView& v, int x, int y, int z, std::size_t c, float g[Q]) {
  if (!kOdd) {
    SHIP_LRM_UNROLL
    for (int i = 0; i < Q; ++i) g[i] = load_pop(pop(v, d3q19::opp(i), c));
    return;
  }
  g[0] = load_pop(pop(v, 0, c));
  const std::int64_t* inner = inner_offsets(v, x, y, z);
  float term[Q], weight[Q];
  for (int i = 1; i < Q; ++i) {
    std::size_t nb;
    float uw[4];
    term[i] = weight[i] = 0.0f;
    if (neighbour_along(v, x, y, z, c, inner, i, +1, nb, uw)) {
      g[i] = load_pop(pop(v, i, nb));
    } else {
      const int k = reflect(v, c, i, false);
      g[i] = load_pop(pop(v, k, c));
      term[i] = wall_term(k, uw);
      weight[i] = uw[3];
    }
  }
  // scatter added (1 + a (rho - 1)) term, rho - 1 the sum of what it emitted
  apply_wall_terms(g, term, weight, -1.0f);
}

// Cell c at equilibrium with state m between steps (kOdd: parity of the next step): the slots that
// step reads as the cell's pre-collision populations (even) or as its post-collision ones, reversed
// (odd; see gather and scatter). A start from rest, and a cell that has just left a moving body.
template <bool kOdd>
SHIP_LRM_HD void set_cell_equilibrium(const LatticeView& v, std::size_t c, const Macro& m) {
  SHIP_LRM_UNROLL
  for (int i = 0; i < Q; ++i) pop(v, kOdd ? d3q19::opp(i) : i, c) = store_pop(equilibrium(i, m.rho, m.u));
}

SHIP_LRM_HD Macro load_aux(const LatticeView& v, std::size_t c) {
  Macro m;
  m.rho = v.aux[c];
  for (int a = 0; a < 3; ++a) m.u[a] = v.aux[(a + 1) * v.ncells + c];
  return m;
}
SHIP_LRM_HD void store_aux(const LatticeView& v, std::size_t c, const Macro& m) {
  v.aux[c] = m.rho;
  for (int a = 0; a < 3; ++a) v.aux[(a + 1) * v.ncells + c] = m.u[a];
}

// Bulk cells: all 18 neighbours are fluid-like cells; the neighbour at c_i is c + off[i] (offsets
// of the cell's class, no checks; the source at -c_i is c + off[opp(i)]). kStoreState: also store
// the pre-collision state in aux (a support cell of the open boundaries; see update_boundary_state).
// (x, y, z): the cell's position (cell_position; scalars, as an array in the caller's vectorised
// loop would be a per-lane array GCC does not vectorise).
template <bool kOdd, int kCollision, int kForce, bool kStoreState = false>
SHIP_LRM_HD void update_bulk_cell(const LatticeView& v, std::size_t c, float x, float y, float z, const std::int64_t* off) {
  const float p[3] = {x, y, z};
  float g[Q];
  SHIP_LRM_UNROLL
  for (int i = 0; i < Q; ++i) g[i] = kOdd ? load_pop(pop(v, d3q19::opp(i), c + off[d3q19::opp(i)])) : load_pop(pop(v, i, c));
  float F[3];
  const Macro m = cell_state<kForce>(v, c, p, g, F);
  if (kStoreState) store_aux(v, c, m);
  collide<kCollision, kForce != kNoForce>(g, m, F, v.params);
  SHIP_LRM_UNROLL
  for (int i = 0; i < Q; ++i) {
    if (kOdd)
      pop(v, i, c + off[i]) = store_pop(g[i]);
    else
      pop(v, d3q19::opp(i), c) = store_pop(g[i]);
  }
}

// Streaming addresses of a run of cells with one link mask, reflection rule and neighbour offsets
// (a Lattice Segment): population i of cell c is read from src[i][c] and its post-collision
// value written to dst[i][c]. Wall links reflect within the cell (offset 0), the others reach
// the neighbour; the even step only permutes the cell's own slots.
template <bool kOdd>
SHIP_LRM_HD void segment_addresses(const LatticeView& v, std::uint32_t mask, int rule, const std::int64_t* off, pop_t* src[Q],
                                   pop_t* dst[Q]) {
  for (int i = 0; i < Q; ++i) {
    const int o = d3q19::opp(i);
    if (!kOdd) {
      src[i] = v.g + i * v.pstride;
      dst[i] = v.g + o * v.pstride;
      continue;
    }
    src[i] = (mask >> o) & 1u ? v.g + d3q19::opp(reflect_by_rule(rule, i, true)) * v.pstride : v.g + o * v.pstride + off[o];
    dst[i] = (mask >> i) & 1u ? v.g + reflect_by_rule(rule, i, false) * v.pstride : v.g + i * v.pstride + off[i];
  }
}

// Pre-collision populations g, force density F and state of cell c of a segment at position
// (x, y, z) (update_segment_cell; the CPU solver's field read-out).
template <int kForce>
SHIP_LRM_HD Macro segment_cell_state(const LatticeView& v, std::size_t c, float x, float y, float z, pop_t* const src[Q], float g[Q],
                                     float F[3]) {
  const float p[3] = {x, y, z};
  SHIP_LRM_UNROLL
  for (int i = 0; i < Q; ++i) g[i] = load_pop(src[i][c]);
  return cell_state<kForce>(v, c, p, g, F);
}

// Update of one cell of a segment at position (x, y, z) (branch-free: the loop over a segment
// vectorises).
template <int kCollision, int kForce, bool kStoreState = false>
SHIP_LRM_HD void update_segment_cell(const LatticeView& v, std::size_t c, float x, float y, float z, pop_t* const src[Q],
                                     pop_t* const dst[Q]) {
  float g[Q], F[3];
  const Macro m = segment_cell_state<kForce>(v, c, x, y, z, src, g, F);
  if (kStoreState) store_aux(v, c, m);
  collide<kCollision, kForce != kNoForce>(g, m, F, v.params);
  SHIP_LRM_UNROLL
  for (int i = 0; i < Q; ++i) dst[i][c] = store_pop(g[i]);
}

// Link mask of a cell next to walls (Lattice::finalize): bit i set when the cell at c + c_i is a
// wall or outside a non-periodic face; kMovingWallLink when one of them moves (then the checked
// gather/scatter, which know the wall velocity per link, are used).
constexpr std::uint32_t kMovingWallLink = 1u << 31;

// gather/scatter for a cell with a known link mask, reaching fluid neighbours through the
// offsets of its cell class: the same streaming without searching the neighbourhood.
template <bool kOdd>
SHIP_LRM_HD void gather_masked(const LatticeView& v, std::size_t c, std::uint32_t mask, const std::int64_t* off, float g[Q]) {
  if (!kOdd) {
    for (int i = 0; i < Q; ++i) g[i] = load_pop(pop(v, i, c));
    return;
  }
  g[0] = load_pop(pop(v, 0, c));
  for (int i = 1; i < Q; ++i) {
    const int o = d3q19::opp(i);
    g[i] = (mask >> o) & 1u ? load_pop(pop(v, d3q19::opp(reflect(v, c, i, true)), c)) : load_pop(pop(v, o, c + off[o]));
  }
}
template <bool kOdd>
SHIP_LRM_HD void scatter_masked(const LatticeView& v, std::size_t c, std::uint32_t mask, const std::int64_t* off, const float g[Q]) {
  if (!kOdd) {
    for (int i = 0; i < Q; ++i) pop(v, d3q19::opp(i), c) = store_pop(g[i]);
    return;
  }
  pop(v, 0, c) = store_pop(g[0]);
  for (int i = 1; i < Q; ++i) {
    if ((mask >> i) & 1u)
      pop(v, reflect(v, c, i, false), c) = store_pop(g[i]);
    else
      pop(v, i, c + off[i]) = store_pop(g[i]);
  }
}

// Streaming of cell c (coordinates x, y, z) with link mask `mask`: masked where it can, checked
// where moving walls need the per-link wall velocity.
template <bool kOdd>
SHIP_LRM_HD void gather_cell(const LatticeView& v, std::size_t c, int x, int y, int z, std::uint32_t mask, float g[Q]) {
  if (mask & kMovingWallLink)
    gather<kOdd>(v, x, y, z, c, g);
  else
    gather_masked<kOdd>(v, c, mask, v.row_offsets + Q * cell_class(v.n, x, y, z), g);
}
template <bool kOdd>
SHIP_LRM_HD void scatter_cell(const LatticeView& v, std::size_t c, int x, int y, int z, std::uint32_t mask, const float g[Q]) {
  if (mask & kMovingWallLink)
    scatter<kOdd>(v, x, y, z, c, g);
  else
    scatter_masked<kOdd>(v, c, mask, v.row_offsets + Q * cell_class(v.n, x, y, z), g);
}

// Fluid cell next to walls or non-periodic faces, with its link mask. With open boundaries (aux)
// its pre-collision state is stored too, as the bulk cells' (few cells; not worth a flag).
template <bool kOdd>
SHIP_LRM_HD void update_wall_cell(const LatticeView& v, std::size_t c, std::uint32_t mask) {
  int x, y, z;
  cell_coords(v, c, x, y, z);
  float g[Q], F[3];
  gather_cell<kOdd>(v, c, x, y, z, mask, g);
  const Macro m = cell_state(v, c, g, F);
  if (v.aux) store_aux(v, c, m);
  collide(g, m, F, v.params);
  scatter_cell<kOdd>(v, c, x, y, z, mask, g);
}

// ---- Open boundaries -------------------------------------------------------------------------

// Macroscopic state at open-boundary cell b from its gathered populations (unknown populations
// hold bounce-back placeholders and are not used), thesis 6.1.3. prev: the state one step ago.
SHIP_LRM_HD Macro boundary_macro(const LatticeView& v, int b, const float g[Q], const Macro& prev) {
  const int axis = v.bnd_normal[b] >> 1;
  const int sgn = (v.bnd_normal[b] & 1) ? 1 : -1;
  const auto t = static_cast<CellType>(v.type[v.bnd_cell[b]] & ~kGeneralBit);
  const float K = zou_he_known_sum(g, axis, sgn);
  Macro m;
  if (t == CellType::VelocityInlet) {
    for (int a = 0; a < 3; ++a) m.u[a] = v.bnd_value[4 * b + a];
    const float un = component(m.u, axis);
    if (v.face_characteristic[v.bnd_normal[b]]) {
      m.rho = characteristic_inlet_density(K, sgn * un);
      set_component(m.u, axis, sgn * characteristic_inlet_velocity(sgn * un, m.rho));
    } else {
      m.rho = K / (1.0f + sgn * un);
    }
    return m;
  }
  if (t == CellType::PressureOutlet) {
    m.rho = v.bnd_value[4 * b];
    const float inward = -sgn * component(prev.u, axis);  // sgn * u[axis] is the outward normal velocity
    if (v.face_total_pressure[v.bnd_normal[b]] && inward > 0.0f) m.rho *= 1.0f - 1.5f * inward * inward;  // c_s^2 = 1/3
  } else {
    // + reference change; the density target relaxed towards the reference (FaceCondition::pressure_relaxation)
    const float relax = v.face_pressure_relaxation[v.bnd_normal[b]];
    m.rho = impedance_density(K, prev.rho - relax * (prev.rho - 1.0f), sgn * component(prev.u, axis) + v.bnd_value[4 * b + 3]);
  }
  SHIP_LRM_UNROLL
  for (int a = 0; a < 3; ++a) m.u[a] = (a == axis) ? sgn * (K / m.rho - 1.0f) : zou_he_tangential_momentum(g, axis, sgn, a) / m.rho;
  return m;
}

// Start state of open-boundary cell b: its aux state with the prescribed velocity (inlet) or
// density (pressure outlet) imposed.
SHIP_LRM_HD void initialize_boundary_state(const LatticeView& v, int b) {
  const std::size_t c = v.bnd_cell[b];
  const auto t = static_cast<CellType>(v.type[c] & ~kGeneralBit);
  Macro m = load_aux(v, c);
  if (t == CellType::VelocityInlet)
    for (int a = 0; a < 3; ++a) m.u[a] = v.bnd_value[4 * b + a];
  if (t == CellType::PressureOutlet) m.rho = v.bnd_value[4 * b];
  store_aux(v, c, m);
}

// Is (x,y,z)+d a fluid-like cell whose aux state is maintained? (Every fluid-like cell within
// two cells along an axis of an open-boundary cell is in the support set.)
// (Scalars, no local array indexed by axis: see component() in hd.hpp.)
SHIP_LRM_HD bool support_cell(const LatticeView& v, int x, int y, int z, int axis, int d, std::size_t& nb) {
  const int n = component(v.n, axis);
  int q = (axis == 0 ? x : (axis == 1 ? y : z)) + d;
  if (q < 0 || q >= n) {
    if (static_cast<FaceType>(v.face[2 * axis + (q >= 0 ? 1 : 0)]) != FaceType::Periodic) return false;
    q = (q + n) % n;
  }
  nb = cell_index(v, axis == 0 ? q : x, axis == 1 ? q : y, axis == 2 ? q : z);
  return !is_wall(static_cast<CellType>(v.type[nb] & ~kGeneralBit));
}

// Finite-difference stencil of the velocity gradient at open-boundary cell c = (x,y,z): along each
// axis b, du/dx_b = sum_k weight[3b+k] u(cell[3b+k]) over the support cells' states (aux), central
// where both neighbours exist, else one-sided of second order where two cells exist, else first
// order, zero where neither neighbour is fluid. Unused entries have weight 0 at c. It depends on
// the cell types only, so Lattice::finalize computes it once per lattice (bnd_grad_cell).
SHIP_LRM_HD void gradient_stencil(const LatticeView& v, int x, int y, int z, std::size_t c, std::uint32_t cell[9], float weight[9]) {
  for (int b = 0; b < 3; ++b) {
    std::uint32_t* k = cell + 3 * b;
    float* w = weight + 3 * b;
    std::size_t p1 = 0, m1 = 0, p2 = 0, m2 = 0;
    const bool hp1 = support_cell(v, x, y, z, b, 1, p1), hm1 = support_cell(v, x, y, z, b, -1, m1);
    k[0] = k[1] = k[2] = static_cast<std::uint32_t>(c);
    w[0] = w[1] = w[2] = 0.0f;
    if (hp1 && hm1) {
      k[0] = static_cast<std::uint32_t>(p1), w[0] = 0.5f;
      k[1] = static_cast<std::uint32_t>(m1), w[1] = -0.5f;
    } else if (hp1) {
      k[0] = static_cast<std::uint32_t>(p1);
      if (support_cell(v, x, y, z, b, 2, p2))
        w[0] = 2.0f, w[1] = -1.5f, k[2] = static_cast<std::uint32_t>(p2), w[2] = -0.5f;
      else
        w[0] = 1.0f, w[1] = -1.0f;
    } else if (hm1) {
      k[0] = static_cast<std::uint32_t>(m1);
      if (support_cell(v, x, y, z, b, -2, m2))
        w[0] = -2.0f, w[1] = 1.5f, k[2] = static_cast<std::uint32_t>(m2), w[2] = 0.5f;
      else
        w[0] = -1.0f, w[1] = 1.0f;
    }
  }
}

// Velocity gradient du_a/dx_b at open-boundary cell b from aux through its stencil.
SHIP_LRM_HD void velocity_gradient(const LatticeView& v, int b, float grad[3][3]) {
  const std::uint32_t* cell = v.bnd_grad_cell + 9 * b;
  const float* w = v.bnd_grad_weight + 9 * b;
  for (int a = 0; a < 3; ++a) {
    const float* u = v.aux + (a + 1) * v.ncells;
    for (int d = 0; d < 3; ++d)
      grad[a][d] = w[3 * d] * u[cell[3 * d]] + w[3 * d + 1] * u[cell[3 * d + 1]] + w[3 * d + 2] * u[cell[3 * d + 2]];
  }
}

SHIP_LRM_HD constexpr bool open_face(FaceType f) {
  return f == FaceType::VelocityInlet || f == FaceType::PressureOutlet || f == FaceType::ImpedanceOutlet;
}

// Is (x,y,z) on two or more open faces (an edge or corner where open boundaries meet)? If so, `diag`
// is its inward diagonal neighbour (one step inwards along each such axis), if that is a fluid
// cell, and `diag2` the next one along the same diagonal (diag itself where that is not fluid).
SHIP_LRM_HD bool open_edge_neighbour(const LatticeView& v, int x, int y, int z, std::size_t& diag, std::size_t& diag2) {
  int p[3] = {x, y, z}, step[3] = {0, 0, 0};
  int faces = 0;
  SHIP_LRM_UNROLL  // constant indices: the arrays stay in registers (component() in hd.hpp)
  for (int a = 0; a < 3; ++a) {
    const bool lo = p[a] == 0 && open_face(static_cast<FaceType>(v.face[2 * a]));
    const bool hi = p[a] == v.n[a] - 1 && open_face(static_cast<FaceType>(v.face[2 * a + 1]));
    if (lo)
      step[a] = 1;
    else if (hi)
      step[a] = -1;
    else
      continue;
    ++faces;
  }
  if (faces < 2) return false;
  auto interior = [&](int k, std::size_t& c) {
    int q[3];
    SHIP_LRM_UNROLL
    for (int a = 0; a < 3; ++a) {
      q[a] = p[a] + k * step[a];
      if (q[a] < 0 || q[a] >= v.n[a]) return false;
    }
    c = cell_index(v, q[0], q[1], q[2]);
    const auto t = static_cast<CellType>(v.type[c] & ~kGeneralBit);
    return !is_wall(t) && !is_open_boundary(t);
  };
  if (!interior(1, diag)) return false;
  if (!interior(2, diag2)) diag2 = diag;
  return true;
}

// Density and velocity of a fluid cell from its pre-collision populations (step parity kOdd):
// bulk cells through their fixed offsets, others by the checked gather. Off the hot path: the LRM
// reads its disk cells so every step, and pass 1 of the open boundaries the few open-boundary cells
// next to another (support_state).
template <bool kOdd>
SHIP_LRM_HD Macro fluid_macro(const LatticeView& v, std::size_t c) {
  int x, y, z;
  cell_coords(v, c, x, y, z);
  float g[Q], F[3];
  if (v.type[c] == static_cast<std::uint8_t>(CellType::Fluid))  // bulk: fixed offsets, no search
    gather_masked<kOdd>(v, c, 0u, v.row_offsets + Q * cell_class(v.n, x, y, z), g);
  else
    gather<kOdd>(v, x, y, z, c, g);
  return cell_state(v, c, g, F);
}

// Pre-collision state of a fluid-like neighbour c of an open-boundary cell during pass 1: the state
// its fluid update stored in aux (c is in the support set), or, for another open-boundary cell,
// from its populations, which only its own pass 2 overwrites.
template <bool kOdd>
SHIP_LRM_HD Macro support_state(const LatticeView& v, std::size_t c) {
  return is_open_boundary(static_cast<CellType>(v.type[c] & ~kGeneralBit)) ? fluid_macro<kOdd>(v, c) : load_aux(v, c);
}

// A step with open boundaries (thesis 6.1.3) runs in three passes, each over all cells of its kind
// before the next begins:
//   0. the fluid cells (update_bulk_cell, update_segment_cell, update_wall_cell); the support cells
//      among them store their pre-collision state in aux;
//   1. update_boundary_state: the state (rho, u) of every open-boundary cell, from its known
//      populations, its state one step ago and its interior neighbours' states;
//   2. update_boundary_cell: each open-boundary cell rebuilt from its state and the velocity
//      gradient of the states around it, collided and streamed.
// Every population slot is read and written by one cell only in a step (AA pattern), so pass 0
// leaves the open-boundary cells' populations as they were.
template <bool kOdd>
SHIP_LRM_HD void update_boundary_state(const LatticeView& v, int b) {
  const std::size_t c = v.bnd_cell[b];
  int x, y, z;
  cell_coords(v, c, x, y, z);
  float g[Q];
  gather_cell<kOdd>(v, c, x, y, z, v.bnd_mask[b], g);
  SHIP_LRM_TRACE_STATE(x, y, z, "pass 1, state a step ago", load_aux(v, c));
  Macro m = boundary_macro(v, b, g, load_aux(v, c));
  SHIP_LRM_TRACE_STATE(x, y, z, "pass 1, boundary_macro", m);
  const auto t = static_cast<CellType>(v.type[c] & ~kGeneralBit);
  std::size_t in;
  const int axis = v.bnd_normal[b] >> 1, sgn = (v.bnd_normal[b] & 1) ? 1 : -1;
  std::size_t diag, diag2;
  if (open_edge_neighbour(v, x, y, z, diag, diag2)) {
    // Edge or corner of two or three open faces: the known-population sums mix in links from
    // across the other face, so take what is not prescribed from the inward diagonal neighbours
    // (extrapolation, as in Guo, Zheng & Shi 2002, Chinese Physics 11, 366; the velocity linearly,
    // which keeps the linear field of a rotating domain) and reconstruct the cell in pass 2.
    const Macro mi = support_state<kOdd>(v, diag);
    const Macro mi2 = diag2 == diag ? mi : support_state<kOdd>(v, diag2);
    if (t != CellType::PressureOutlet) m.rho = mi.rho;
    if (t != CellType::VelocityInlet)
      for (int a = 0; a < 3; ++a) m.u[a] = 2.0f * mi.u[a] - mi2.u[a];
    else if (v.face_characteristic[v.bnd_normal[b]])  // the outgoing wave with this density, not boundary_macro's from the mixed sums
      set_component(m.u, axis, sgn * characteristic_inlet_velocity(sgn * v.bnd_value[4 * b + axis], m.rho));
  } else if (t == CellType::ImpedanceOutlet && support_cell(v, x, y, z, axis, -sgn, in)) {
    // Tangential velocity extrapolated linearly from the two interior neighbours along the normal
    // (zero second derivative): the Zou-He estimate from the known populations is biased by the
    // normal flow (6 % of a 3 m/s cross-flow at 10 m/s through-flow), and a zero gradient drifts in
    // a rotating domain, where the tangential velocity -omega x r varies along the normal. Density
    // and normal velocity stay those of eq. 6.15.
    // Where the flow enters (u.n < 0) the tangential velocity comes from outside instead: the
    // reference flow's (characteristic reasoning: vorticity is carried inwards; Poinsot & Lele 1992,
    // J. Comput. Phys. 101, 104, table IV).
    const Macro mi = support_state<kOdd>(v, in);
    std::size_t in2;
    const bool second =
        support_cell(v, x, y, z, axis, -2 * sgn, in2) && !is_open_boundary(static_cast<CellType>(v.type[in2] & ~kGeneralBit));
    const Macro mi2 = second ? support_state<kOdd>(v, in2) : mi;
    const bool inflow = v.face_inflow_reference[v.bnd_normal[b]] && sgn * component(m.u, axis) < 0.0f;
    SHIP_LRM_TRACE_STATE(x, y, z, "pass 1, impedance branch: inner neighbour", mi);
    SHIP_LRM_TRACE_STATE(x, y, z, inflow ? "pass 1, impedance branch (inflow): 2nd neighbour" : "pass 1, impedance branch (outflow): 2nd neighbour",
                         mi2);
    for (int a = 0; a < 3; ++a)
      if (a != axis) m.u[a] = inflow ? v.bnd_value[4 * b + a] : 2.0f * mi.u[a] - mi2.u[a];
  } else if (t == CellType::PressureOutlet && support_cell(v, x, y, z, axis, -sgn, in)) {
    // Neumann-type outflow (thesis 6.1.3): the velocity of the interior neighbour (zero normal
    // gradient) at the same time level, with the prescribed density. Taking u from the known
    // populations instead (Zou & He) is unstable next to no-slip walls.
    const Macro mi = support_state<kOdd>(v, in);
    for (int a = 0; a < 3; ++a) m.u[a] = mi.u[a];
  }
  SHIP_LRM_TRACE_STATE(x, y, z, "pass 1, stored", m);
  store_aux(v, c, m);
}

// Pass 2 (after pass 1 over all open-boundary cells). Every open-boundary cell is rebuilt from its
// state (rho, u) and the velocity gradient (Latt et al. 2008). The impedance outlet's state comes from
// eq. 6.15; the thesis completes it with the non-equilibrium bounce-back of the unknown populations,
// which disturbed a uniform stream running along an impedance face (top and bottom of the LRM
// domain) by several per cent; the full reconstruction keeps it exact and still absorbs an acoustic
// pulse (tests in test_boundaries.cpp). The old populations are not needed.
// In three parts, so that the CPU backend can vectorise the arithmetic over many cells:
// boundary_strain (neighbour look-ups), boundary_collide (per cell arithmetic), scatter_cell.

// Strain rate S = (grad u + grad u^T) / 2 (xx yy zz xy xz yz) at open-boundary cell b.
SHIP_LRM_HD void boundary_strain(const LatticeView& v, int b, float S[6]) {
  float grad[3][3];
  velocity_gradient(v, b, grad);
  S[0] = grad[0][0];
  S[1] = grad[1][1];
  S[2] = grad[2][2];
  S[3] = 0.5f * (grad[0][1] + grad[1][0]);
  S[4] = 0.5f * (grad[0][2] + grad[2][0]);
  S[5] = 0.5f * (grad[1][2] + grad[2][1]);
}

// Streams the post-collision populations g of open-boundary cell b.
template <bool kOdd>
SHIP_LRM_HD void scatter_boundary_cell(const LatticeView& v, int b, const float g[Q]) {
  const std::size_t c = v.bnd_cell[b];
  int x, y, z;
  cell_coords(v, c, x, y, z);
  scatter_cell<kOdd>(v, c, x, y, z, v.bnd_mask[b], g);
}

// Inputs of boundary_collide for open-boundary cell b: its state m (from pass 1), strain rate S, base
// force F and position p.
template <int kForce>
SHIP_LRM_HD void boundary_inputs(const LatticeView& v, int b, Macro& m, float S[6], float F[3], float p[3]) {
  const std::size_t c = v.bnd_cell[b];
  m = load_aux(v, c);
  boundary_strain(v, b, S);
  base_force<kForce>(v, c, F);
  p[0] = p[1] = p[2] = 0.0f;
  if (has_frame_force(kForce)) cell_position(v, c, p);
}

// Post-collision populations g of an open-boundary cell rebuilt from boundary_inputs (no access to
// the lattice's per-cell arrays, so that a loop over cells vectorises without gathers).
template <int kCollision, int kForce>
SHIP_LRM_HD void boundary_collide(const LatticeView& v, const Macro& m, const float S[6], const float F0[3], const float p[3], float g[Q]) {
  float F[3] = {F0[0], F0[1], F0[2]};
  reconstruct_fd(g, m.rho, m.u, S, omega_from_nu(v.params.nu));
  collide<kCollision, kForce != kNoForce>(g, collision_state<kForce>(v, p, g, F), F, v.params);
}

// Pass 2 for one open-boundary cell b, with the model and force as template parameters.
template <bool kOdd, int kCollision, int kForce>
SHIP_LRM_HD void update_boundary_cell(const LatticeView& v, int b) {
  Macro m;
  float S[6], F[3], p[3], g[Q];
  boundary_inputs<kForce>(v, b, m, S, F, p);
  boundary_collide<kCollision, kForce>(v, m, S, F, p, g);
  scatter_boundary_cell<kOdd>(v, b, g);
}

// Divergence guard, local and cheap: density and speed of cell c from its own 19 slots. Between
// steps these hold the pre-collision populations (next step even) or the post-collision ones in
// reversed slots (next step odd, kOdd); both give rho exactly and the momentum up to one step's
// force, enough to catch a non-finite or non-positive density and a runaway speed.
template <bool kOdd>
SHIP_LRM_HD bool cell_diverged(const LatticeView& v, std::size_t c, float limit2) {
  if (is_wall(static_cast<CellType>(v.type[c] & ~kGeneralBit))) return false;
  float g[Q];
  SHIP_LRM_UNROLL
  for (int i = 0; i < Q; ++i) g[i] = load_pop(pop(v, kOdd ? d3q19::opp(i) : i, c));
  float rho, j[3];
  moments(g, rho, j);
  const float s2 = (j[0] * j[0] + j[1] * j[1] + j[2] * j[2]) / (rho * rho);
  return !(s2 <= limit2) || !(rho > 0.0f);
}

// Macroscopic state of a fluid-like cell for output, valid between steps (kOdd: parity of the
// next step). Open-boundary cells report the state their boundary condition imposed last step.
template <bool kOdd>
SHIP_LRM_HD Macro cell_macro(const LatticeView& v, std::size_t c) {
  return is_open_boundary(static_cast<CellType>(v.type[c] & ~kGeneralBit)) ? load_aux(v, c) : fluid_macro<kOdd>(v, c);
}

// Held cell h (Lattice::set_held) after a step of parity kOddDone: the populations it emitted in
// that step, wherever the step stored them (scatter: its own slots after an even step, its
// neighbours' after an odd one, wall links reflected with Ladd's term), are replaced by the
// equilibrium with the same mass and its body's velocity at the cell centre. In the A-A pattern a
// cell emits twice per pair of steps (its even-step populations, which the odd step streams, and its
// odd-step ones, stored straight into the neighbours' slots), so everything a held cell sends its
// neighbours moves with the body, and no mass is made or lost. Only the cell itself writes these
// slots in a step, so held cells can be processed in any order, in parallel.
template <bool kOddDone>
SHIP_LRM_HD void hold_cell(const LatticeView& v, int h) {
  const std::size_t c = v.held_cell[h];
  int x, y, z;
  cell_coords(v, c, x, y, z);
  float g[Q];
  emitted<kOddDone>(v, x, y, z, c, g);
  float rho, j[3], u[3] = {0.0f, 0.0f, 0.0f};
  moments(g, rho, j);
  if (v.held_wall[h] != kHeldWallAtRest)
    rigid_velocity(v.walls[v.held_wall[h]], static_cast<float>(x), static_cast<float>(y), static_cast<float>(z), u);
  SHIP_LRM_UNROLL
  for (int i = 0; i < Q; ++i) g[i] = equilibrium(i, rho, u);
  scatter<kOddDone>(v, x, y, z, c, g);
}

// Absorbing-layer cell a (FaceCondition::absorbing_cells) after a step of parity kOddDone: the
// velocity of the populations it emitted moves by sigma towards its face cell's prescribed velocity
// u_t, u' = u + sigma (u_t - u), through the equilibrium part only (g += f_eq(rho, u') - f_eq(rho, u)):
// mass and the non-equilibrium part stay (a relaxation of the velocity, not of the viscosity). The
// list holds plain fluid cells only, each once. Only the cell itself writes these slots (see
// hold_cell), so its cells can be processed in any order, in parallel.
template <bool kOddDone>
SHIP_LRM_HD void absorb_cell(const LatticeView& v, int a) {
  const std::size_t c = v.absorbing_cell[a];
  int x, y, z;
  cell_coords(v, c, x, y, z);
  float g[Q];
  emitted<kOddDone>(v, x, y, z, c, g);
  float rho, j[3], u[3], ut[3];
  moments(g, rho, j);
  const float sigma = v.absorbing_sigma[a], *target = v.bnd_value + 4 * static_cast<std::size_t>(v.absorbing_target[a]);
  for (int k = 0; k < 3; ++k) {
    u[k] = j[k] / rho;
    ut[k] = u[k] + sigma * (target[k] - u[k]);
  }
  SHIP_LRM_UNROLL
  for (int i = 0; i < Q; ++i) g[i] += equilibrium(i, rho, ut) - equilibrium(i, rho, u);
  scatter<kOddDone>(v, x, y, z, c, g);
}

}  // namespace ship_lrm::lbm
