// CPU backend: OpenMP over the cell lists of the Lattice, per-cell physics from lattice_view.hpp.
#include <omp.h>
#include <sys/mman.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <memory>
#include <type_traits>
#include <utility>

#include "ship_lrm/lbm/solver.hpp"
#include "ship_lrm/lbm/team_loop.hpp"

namespace ship_lrm::lbm {
namespace {

// Population storage: 2 MiB-aligned and backed by transparent huge pages where the kernel offers
// them (madvise), so the 38 concurrent streams of a step do not thrash the TLB.
class PopulationBuffer {
 public:
  explicit PopulationBuffer(std::size_t n) : n_(n) {
    constexpr std::size_t kHuge = std::size_t(2) << 20;
    const std::size_t bytes = (n * sizeof(pop_t) + kHuge - 1) / kHuge * kHuge;
    p_.reset(static_cast<pop_t*>(std::aligned_alloc(kHuge, bytes)));
    if (!p_) throw std::bad_alloc();
#ifdef MADV_HUGEPAGE
    madvise(p_.get(), bytes, MADV_HUGEPAGE);
#endif
  }
  pop_t* data() const { return p_.get(); }
  std::size_t size() const { return n_; }

 private:
  struct Free {
    void operator()(pop_t* p) const { std::free(p); }
  };
  std::unique_ptr<pop_t, Free> p_;
  std::size_t n_;
};

class CpuSolver final : public Solver {
 public:
  explicit CpuSolver(Lattice lattice) : Solver(std::move(lattice)), g_(Q * view_.pstride) {
    const std::size_t n = lattice_.cells();
    if (!lattice_.boundary_cells().empty()) aux_.assign(4 * n, 0.0f);
    bnd_value_ = lattice_.boundary_values();
    sync_view();
    do_initialize({}, {});
  }
  const char* backend_name() const override { return "cpu"; }

  void set_force_field(const std::vector<float>& f) override {
    const std::size_t n = lattice_.cells();
    if (f.empty()) {
      force_.clear();
    } else {
      if (f.size() != 3 * n) throw ConfigError("set_force_field: expected 3 values per cell");
      for (float x : f)
        if (!std::isfinite(x)) throw ConfigError("set_force_field: force is not finite");
      force_.resize(3 * n);
      for (std::size_t c = 0; c < n; ++c)
        for (int a = 0; a < 3; ++a) force_[a * n + c] = f[3 * c + a];
    }
    mark_forced_segments();
    sync_view();
  }

  bool in_place_walls() const override { return true; }

  void do_set_boundary_values(const std::vector<float>& values) override {
    bnd_value_ = values;
    sync_view();
  }

  void do_set_populations(const std::vector<float>& g) override {
    const std::size_t n = lattice_.cells();
    for (int i = 0; i < Q; ++i)
      for (std::size_t c = 0; c < n; ++c) pop(view_, i, c) = store_pop(g[i * n + c]);
  }
  std::vector<float> populations() override {
    const std::size_t n = lattice_.cells();
    std::vector<float> out(Q * n);
    for (int i = 0; i < Q; ++i)
      for (std::size_t c = 0; c < n; ++c) out[i * n + c] = load_pop(pop(view_, i, c));
    return out;
  }
  std::vector<float> do_cell_state() override { return aux_; }
  void do_set_cell_state(const std::vector<float>& a) override { std::copy(a.begin(), a.end(), aux_.begin()); }

 protected:
  void sync_view() override {
    view_.g = g_.data();
    view_.type = lattice_.types().data();
    view_.tag = lattice_.tags().data();
    view_.walls = lattice_.wall_motions().data();
    view_.force = force_.empty() ? nullptr : force_.data();
    view_.bnd_cell = lattice_.boundary_cells().data();
    view_.bnd_normal = lattice_.boundary_normals().data();
    view_.bnd_mask = lattice_.boundary_link_masks().data();
    view_.bnd_value = bnd_value_.data();
    view_.aux = aux_.empty() ? nullptr : aux_.data();
    view_.row_offsets = lattice_.row_offsets().data();
    view_.bnd_grad_cell = lattice_.boundary_gradient_cells().data();
    view_.bnd_grad_weight = lattice_.boundary_gradient_weights().data();
    view_.held_cell = lattice_.held_cells().data();
    view_.held_wall = lattice_.held_walls().data();
    view_.absorbing_cell = lattice_.absorbing_cells().data();
    view_.absorbing_target = lattice_.absorbing_targets().data();
    view_.absorbing_sigma = lattice_.absorbing_sigmas().data();
  }

  void do_initialize(const std::vector<float>& rho, const std::vector<float>& u) override {
    const std::size_t n = lattice_.cells();
    const LatticeView& v = view_;
    // vectorised across cells (the LRM restarts its whole flow this way at each wall change next to
    // the faces, dozens of times a second low over the sea); a start from rest takes the same loop
    const std::vector<float> rest_rho(rho.empty() ? n : 0, 1.0f), rest_u(u.empty() ? 3 * n : 0, 0.0f);
    const float* r = rho.empty() ? rest_rho.data() : rho.data();
    const float* w = u.empty() ? rest_u.data() : u.data();
    v.aux ? equilibrium_cells<true>(r, w) : equilibrium_cells<false>(r, w);
    for (int b = 0; b < v.nbnd; ++b) initialize_boundary_state(v, b);  // prescribed start state
  }

  // Every cell at equilibrium with density r[c] and velocity w[3c..3c+2] before an even step
  // (kAux: the state stored too). The view is copied so that its pointers stay in registers: the
  // stores could alias a referenced view's members, and the loop did not vectorise.
  template <bool kAux>
  void equilibrium_cells(const float* r, const float* w) {
    const LatticeView v = view_;
    const long n = static_cast<long>(lattice_.cells());
    // (ivdep, not `omp simd`: that makes the Macro a per-lane array, which GCC 12 does not vectorise)
#pragma omp parallel
    {
      const long t = omp_get_thread_num(), threads = omp_get_num_threads();
      const long c1 = n * (t + 1) / threads;
#pragma GCC ivdep
      for (long c = n * t / threads; c < c1; ++c) {
        Macro m;
        m.rho = r[c];
        for (int a = 0; a < 3; ++a) m.u[a] = w[3 * c + a];
        set_cell_equilibrium<false>(v, static_cast<std::size_t>(c), m);
        if (kAux) store_aux(v, static_cast<std::size_t>(c), m);
      }
    }
  }

  // One segment of fluid cells (see Segment): bulk cells through fixed offsets, cells next to
  // resting walls through one table of addresses; both loops vectorise. The vector loops take whole
  // groups of kLanes cells; the rest of the segment (fewer) goes through update_segment_rest.
  template <bool kOdd, int kCollision, int kForce, bool kStoreState>
  void update_segment(const Segment& sg) {
    const LatticeView& v = view_;
    const std::int64_t* off = v.row_offsets + Q * sg.cell_class;
    const std::size_t first = sg.first, last = first + sg.count, whole = first + sg.count / kLanes * kLanes;
    // a segment lies in one row (Lattice::finalize): its cells' positions without a division
    int x0, y0, z0;
    cell_coords(v, first, x0, y0, z0);
    const float y = static_cast<float>(y0), z = static_cast<float>(z0);
    pop_t* src[Q];
    pop_t* dst[Q];
    segment_addresses<kOdd>(v, sg.link_mask, sg.reflection, off, src, dst);
    if (sg.link_mask == 0) {
#pragma omp simd
      for (std::size_t c = first; c < whole; ++c)
        update_bulk_cell<kOdd, kCollision, kForce, kStoreState>(v, c, static_cast<float>(x0 + static_cast<int>(c - first)), y, z, off);
    } else {
#pragma omp simd
      for (std::size_t c = first; c < whole; ++c)
        update_segment_cell<kCollision, kForce, kStoreState>(v, c, static_cast<float>(x0 + static_cast<int>(c - first)), y, z, src, dst);
    }
    if (whole < last)
      update_segment_rest<kCollision, kForce, kStoreState>(whole, last, static_cast<float>(x0 + static_cast<int>(whole - first)), y, z, src,
                                                           dst);
  }

  // The last cells [c0, c1) of a segment, fewer than kLanes, at positions x0, x0 + 1, ...: a loop with
  // a variable count this short runs scalar (GCC 12 has no masked tails), and the LRM's rows leave
  // 6 of their 38 bulk cells here at N = 32, which took two thirds of the fluid pass. So they are
  // copied into kLanes lanes (the spare ones a fluid at rest), updated there by the same per-cell
  // code in one vector pass, and copied back; a view whose per-cell arrays are those lanes
  // (ncells = kLanes) serves the force field and the stored states.
  template <int kCollision, int kForce, bool kStoreState>
  void update_segment_rest(std::size_t c0, std::size_t c1, float x0, float y, float z, pop_t* const src[Q], pop_t* const dst[Q]) {
    const LatticeView& v = view_;
    const std::size_t n = c1 - c0;
    alignas(64) pop_t in[Q][kLanes], out[Q][kLanes];
    alignas(64) float force[3][kLanes], aux[4][kLanes];
    pop_t* lane_in[Q];
    pop_t* lane_out[Q];
    for (int i = 0; i < Q; ++i) {
      lane_in[i] = in[i];
      lane_out[i] = out[i];
      copy_lanes(in[i], src[i] + c0, n, store_pop(0.0f));
    }
    LatticeView lanes = v;
    lanes.ncells = kLanes;
    lanes.force = has_force_field(kForce) ? &force[0][0] : nullptr;
    lanes.aux = &aux[0][0];
    if (has_force_field(kForce)) {
      for (int a = 0; a < 3; ++a) copy_lanes(force[a], v.force + a * v.ncells + c0, n, 0.0f);
    }
    // the lane's x through a 32-bit int: a 64-bit integer does not convert to float in AVX2 vectors,
    // and the frame's forces (which need x) made this loop scalar there (0.4 of the turning step)
#pragma omp simd
    for (int k = 0; k < static_cast<int>(kLanes); ++k)
      update_segment_cell<kCollision, kForce, kStoreState>(lanes, k, x0 + static_cast<float>(k), y, z, lane_in, lane_out);
    for (int i = 0; i < Q; ++i) store_lanes(dst[i] + c0, out[i], n);
    if (kStoreState)
      for (int a = 0; a < 4; ++a) store_lanes(v.aux + a * v.ncells + c0, aux[a], n);
  }
  // to[k] = from[k] for k < n, `spare` beyond; from[k] is not read for k >= n.
  template <class T>
  static void copy_lanes(T* to, const T* from, std::size_t n, T spare) {
#pragma omp simd
    for (std::size_t k = 0; k < kLanes; ++k) to[k] = spare;
    copy_first(to, from, n);
  }
  // to[k] = from[k] for k < n only (the slots beyond belong to other cells).
  template <class T>
  static void store_lanes(T* to, const T* from, std::size_t n) {
    copy_first(to, from, n);
  }
  // The first n < kLanes values, through a copy of fixed length per n: the compiler turns each into
  // a few whole moves. Masked vector loads and stores (vmaskmovps) took half of update_segment_rest
  // on an AVX2 AMD machine, and a loop of variable length runs scalar.
  template <class T>
  static void copy_first(T* to, const T* from, std::size_t n) {
    copy_first(to, from, n, std::make_index_sequence<kLanes>{});
  }
  template <class T, std::size_t... kN>
  static void copy_first(T* to, const T* from, std::size_t n, std::index_sequence<kN...>) {
    ((n == kN ? copy_fixed<kN>(to, from) : void()), ...);
  }
  template <std::size_t kN, class T>
  static void copy_fixed(T* to, const T* from) {
    for (std::size_t k = 0; k < kN; ++k) to[k] = from[k];
  }

  template <bool kOdd, int kCollision, int kForce>
  void update_segment(const Segment& sg, bool store) {
    store ? update_segment<kOdd, kCollision, kForce, true>(sg) : update_segment<kOdd, kCollision, kForce, false>(sg);
  }

  // Cells without a field force while the field is on (the rotor's force density covers a few per
  // cent of the LRM's cells at most) take the same update without the field's loads (and, where no
  // other force is left, without the Guo source terms of a zero force): segments (segment_forced_)
  // and boundary blocks that hold none. body(mode) runs the update with force mode kForce, or, where
  // `forced` is false, with kForce's mode less the field (an std::integral_constant).
  template <int kForce, class Body>
  void with_field_if(bool forced, Body&& body) const {
    using Mode = std::integral_constant<int, kForce>;
    if constexpr (!has_force_field(kForce)) {
      body(Mode{});
    } else if (forced) {
      body(Mode{});
    } else if constexpr (kForce == kFrameForceField) {
      body(std::integral_constant<int, kFrameForce>{});
    } else if (uniform_force_set(view_)) {
      body(std::integral_constant<int, kUniformForce>{});
    } else {
      body(std::integral_constant<int, kNoForce>{});
    }
  }
  void mark_forced_segments() {
    const auto& segs = lattice_.bulk_segments();
    listed_cells_.clear();  // their segments are looked up again
    segment_forced_.assign(segs.size(), 0);
    for (std::size_t s = 0; s < segs.size() && !force_.empty(); ++s)
      for (std::size_t c = segs[s].first; c < segs[s].first + segs[s].count && !segment_forced_[s]; ++c)
        segment_forced_[s] = field_force_at(c);
  }
  bool field_force_at(std::size_t c) const {
    const std::size_t n = lattice_.cells();
    return force_[c] != 0.0f || force_[n + c] != 0.0f || force_[2 * n + c] != 0.0f;
  }

  // Pass 2 of the open boundaries for cells b0 .. b0 + kBoundaryBlock - 1: the neighbour look-ups
  // and the streaming per cell, the arithmetic between them vectorised across the block. The
  // inputs are kept as columns (rho, u, S, F, p): strided or indirect loads would stop GCC from
  // vectorising (it emits no gathers for AMD Zen, and none for groups of 3).
  static constexpr int kBoundaryBlock = 64;
  template <bool kOdd, int kCollision, int kForce>
  void update_boundary_block(int b0) {
    const LatticeView& v = view_;
    const int n = std::min(kBoundaryBlock, v.nbnd - b0);
    if constexpr (has_force_field(kForce)) {  // a block without a field force skips it (with_field_if)
      bool forced = false;
      for (int k = 0; k < n && !forced; ++k) forced = field_force_at(v.bnd_cell[b0 + k]);
      if (!forced)
        return with_field_if<kForce>(false, [&](auto mode) { update_boundary_block<kOdd, kCollision, decltype(mode)::value>(b0); });
    }
    alignas(64) float X[16][kBoundaryBlock];
    alignas(64) float G[Q][kBoundaryBlock];
    for (int k = 0; k < n; ++k) {
      Macro m;
      float S[6], F[3], p[3];
      boundary_inputs<kForce>(v, b0 + k, m, S, F, p);
      X[0][k] = m.rho;
      for (int a = 0; a < 3; ++a) X[1 + a][k] = m.u[a], X[10 + a][k] = F[a], X[13 + a][k] = p[a];
      for (int a = 0; a < 6; ++a) X[4 + a][k] = S[a];
    }
#pragma GCC ivdep
    for (int k = 0; k < n; ++k) {
      Macro m;
      m.rho = X[0][k];
      m.u[0] = X[1][k], m.u[1] = X[2][k], m.u[2] = X[3][k];
      const float S[6] = {X[4][k], X[5][k], X[6][k], X[7][k], X[8][k], X[9][k]};
      const float F[3] = {X[10][k], X[11][k], X[12][k]};
      const float p[3] = {X[13][k], X[14][k], X[15][k]};
      float g[Q];
      boundary_collide<kCollision, kForce>(v, m, S, F, p, g);
      SHIP_LRM_UNROLL
      for (int i = 0; i < Q; ++i) G[i][k] = g[i];
    }
    for (int k = 0; k < n; ++k) {
      float g[Q];
      for (int i = 0; i < Q; ++i) g[i] = G[i][k];
      scatter_boundary_cell<kOdd>(v, b0 + k, g);
    }
  }

  // The passes of a step (see update_boundary_state in lattice_view.hpp), then the held cells
  // (hold_cell) and the absorbing layers' cells (absorb_cell), in one parallel region. Each loop is a TeamLoop (team_loop.hpp): a static
  // share per thread that the others finish when it is held up.
  template <bool kOdd, int kCollision, int kForce>
  void run_step() {
    const LatticeView& v = view_;
    const auto& segs = lattice_.bulk_segments();
    const auto& general = lattice_.general_cells();
    const auto& masks = lattice_.general_link_masks();
    const long nseg = static_cast<long>(segs.size()), ng = static_cast<long>(general.size());
    const bool store = v.aux != nullptr;
    const int threads = omp_get_max_threads();
    const long nblocks = (v.nbnd + kBoundaryBlock - 1) / kBoundaryBlock;
    loops_[0].reset(nseg, threads, kSegmentChunk);
    loops_[1].reset(ng, threads, kGeneralChunk);
    loops_[2].reset(v.nbnd, threads, kBoundaryChunk);
    loops_[3].reset(nblocks, threads, kBlockChunk);
    loops_[4].reset(v.nheld, threads, kHeldChunk);
    loops_[5].reset(v.nabsorbing, threads, kHeldChunk);
#pragma omp parallel
    {
      const int t = omp_get_thread_num();
      loops_[0].run(t, [&](long s) {
        const bool st = store && segs[s].store_state;
        const bool forced = has_force_field(kForce) && segment_forced_[s];  // (sized only once a field is set)
        with_field_if<kForce>(forced, [&](auto mode) { update_segment<kOdd, kCollision, decltype(mode)::value>(segs[s], st); });
      });
      loops_[1].run(t, [&](long k) { update_wall_cell<kOdd>(v, general[k], masks[k]); });
      if (v.nbnd) {
#pragma omp barrier
        // every support cell's state is stored
        loops_[2].run(t, [&](long b) { update_boundary_state<kOdd>(v, static_cast<int>(b)); });
#pragma omp barrier
        loops_[3].run(t, [&](long k) { update_boundary_block<kOdd, kCollision, kForce>(static_cast<int>(k * kBoundaryBlock)); });
      }
      if (v.nheld) {
#pragma omp barrier
        // every cell has emitted this step's populations
        loops_[4].run(t, [&](long h) { hold_cell<kOdd>(v, static_cast<int>(h)); });
      }
      if (v.nabsorbing) {
#pragma omp barrier
        // every cell has emitted this step's populations (the lists of held and absorbing cells are disjoint)
        loops_[5].run(t, [&](long a) { absorb_cell<kOdd>(v, static_cast<int>(a)); });
      }
    }
  }

  template <bool kOdd, int kCollision>
  void run_step_forced() {
    switch (force_mode(view_)) {
      case kNoForce:
        return run_step<kOdd, kCollision, kNoForce>();
      case kUniformForce:
        return run_step<kOdd, kCollision, kUniformForce>();
      case kForceField:
        return run_step<kOdd, kCollision, kForceField>();
      case kFrameForce:
        return run_step<kOdd, kCollision, kFrameForce>();
      default:
        return run_step<kOdd, kCollision, kFrameForceField>();
    }
  }
  template <bool kOdd>
  void run_step_dispatch() {
    with_collision_kind(view_.params, [&](auto kind) { run_step_forced<kOdd, decltype(kind)::value>(); });
  }
  void do_step(bool odd) override { odd ? run_step_dispatch<true>() : run_step_dispatch<false>(); }

  template <bool kOdd>
  Macro macro_at(std::size_t c) const {
    const auto t = static_cast<CellType>(lattice_.types()[c] & ~kGeneralBit);
    if (is_wall(t)) return Macro{};
    return cell_macro<kOdd>(view_, c);
  }

  void do_velocities(bool next_odd, const std::vector<std::uint32_t>& cells, std::vector<float>& out) override {
    for (std::size_t k = 0; k < cells.size(); ++k) {
      const Macro m = next_odd ? macro_at<true>(cells[k]) : macro_at<false>(cells[k]);
      for (int a = 0; a < 3; ++a) out[3 * k + a] = m.u[a];
    }
  }

  void do_set_cell_forces(const std::vector<std::uint32_t>& cells, const std::vector<float>& f) override {
    const std::size_t n = lattice_.cells();
    if (force_.empty()) {
      force_.assign(3 * n, 0.0f);
      sync_view();
    }
    const auto& segs = lattice_.bulk_segments();
    if (segment_forced_.size() != segs.size()) segment_forced_.assign(segs.size(), 0);
    if (cells != listed_cells_) {  // the segment that holds each cell, if any (other cells take the checked path)
      listed_cells_ = cells;
      listed_segment_.assign(cells.size(), -1);
      for (std::size_t k = 0; k < cells.size(); ++k) {  // (segments are in cell order)
        const auto it =
            std::upper_bound(segs.begin(), segs.end(), cells[k], [](std::uint32_t c, const Segment& sg) { return c < sg.first; });
        if (it == segs.begin()) continue;
        const std::size_t s = static_cast<std::size_t>(it - segs.begin()) - 1;
        if (cells[k] < segs[s].first + segs[s].count) listed_segment_[k] = static_cast<std::int64_t>(s);
      }
    }
    for (std::size_t k = 0; k < cells.size(); ++k) {
      for (int a = 0; a < 3; ++a) force_[a * n + cells[k]] = f[3 * k + a];
      if (f[3 * k] == 0.0f && f[3 * k + 1] == 0.0f && f[3 * k + 2] == 0.0f) continue;
      if (listed_segment_[k] >= 0) segment_forced_[static_cast<std::size_t>(listed_segment_[k])] = 1;
    }
  }

  Macro do_cell_state(bool next_odd, std::size_t c) override { return next_odd ? macro_at<true>(c) : macro_at<false>(c); }

  void do_change_walls(Lattice&& next, const std::vector<std::uint32_t>& freed, const std::vector<std::array<float, 4>>& states) override {
    lattice_ = std::move(next);
    sync_view();
    mark_forced_segments();
    const bool odd = steps_ % 2 == 1;
    for (std::size_t k = 0; k < freed.size(); ++k) {
      Macro m;
      m.rho = states[k][0];
      for (int a = 0; a < 3; ++a) m.u[a] = states[k][1 + a];
      odd ? set_cell_equilibrium<true>(view_, freed[k], m) : set_cell_equilibrium<false>(view_, freed[k], m);
      if (view_.aux) store_aux(view_, freed[k], m);
    }
  }

  void do_fields(bool next_odd, Fields& out) override { next_odd ? fields<true>(out) : fields<false>(out); }

  // The fields cell by cell as macro_at gives them, the bulk segments through their streaming
  // addresses (vectorised, positions without an index division): the in-place restart next to the
  // faces reads them at every wall change there, and cell by cell this took as long as a step.
  template <bool kOdd>
  void fields(Fields& out) {
    const LatticeView& v = view_;
    const auto& segs = lattice_.bulk_segments();
    const auto& general = lattice_.general_cells();
    const long n = static_cast<long>(lattice_.cells()), nseg = static_cast<long>(segs.size()), ng = static_cast<long>(general.size());
    const int mode = force_mode(v);
    const auto put = [&](std::size_t c, const Macro& m) {
      out.rho[c] = m.rho;
      for (int a = 0; a < 3; ++a) out.u[3 * c + a] = m.u[a];
    };
#pragma omp parallel
    {
#pragma omp for schedule(static) nowait
      for (long c = 0; c < n; ++c) {  // walls and open-boundary cells
        const auto t = static_cast<CellType>(v.type[c] & ~kGeneralBit);
        if (is_wall(t) || is_open_boundary(t)) put(c, macro_at<kOdd>(c));
      }
#pragma omp for schedule(static) nowait
      for (long k = 0; k < ng; ++k) put(general[k], macro_at<kOdd>(general[k]));  // next to moving walls
#pragma omp for schedule(static)
      for (long k = 0; k < nseg; ++k) {
        switch (mode) {
          case kNoForce:
            segment_fields<kOdd, kNoForce>(segs[k], out);
            break;
          case kUniformForce:
            segment_fields<kOdd, kUniformForce>(segs[k], out);
            break;
          case kForceField:
            segment_fields<kOdd, kForceField>(segs[k], out);
            break;
          case kFrameForce:
            segment_fields<kOdd, kFrameForce>(segs[k], out);
            break;
          default:
            segment_fields<kOdd, kFrameForceField>(segs[k], out);
        }
      }
    }
  }
  template <bool kOdd, int kForce>
  void segment_fields(const Segment& sg, Fields& out) {
    const LatticeView& v = view_;
    pop_t* src[Q];
    pop_t* dst[Q];
    segment_addresses<kOdd>(v, sg.link_mask, sg.reflection, v.row_offsets + Q * sg.cell_class, src, dst);
    int x0, y0, z0;
    cell_coords(v, sg.first, x0, y0, z0);
    const float y = static_cast<float>(y0), z = static_cast<float>(z0);
    float* rho = out.rho.data();
    float* u = out.u.data();
    const std::size_t first = sg.first, last = first + sg.count;
#pragma omp simd
    for (std::size_t c = first; c < last; ++c)
      store_fields<kForce>(v, c, static_cast<float>(x0 + static_cast<int>(c - first)), y, z, src, rho, u);
  }
  template <int kForce>
  static void store_fields(const LatticeView& v, std::size_t c, float x, float y, float z, pop_t* const src[Q], float* rho, float* u) {
    float g[Q], F[3];
    const Macro m = segment_cell_state<kForce>(v, c, x, y, z, src, g, F);
    rho[c] = m.rho;
    for (int a = 0; a < 3; ++a) u[3 * c + a] = m.u[a];
  }

  long long do_find_divergent(bool next_odd, float limit) override {
    const long n = static_cast<long>(lattice_.cells());
    long long first = std::numeric_limits<long long>::max();
#pragma omp parallel for schedule(static) reduction(min : first)
    for (long c = 0; c < n; ++c) {
      const bool bad = next_odd ? cell_diverged<true>(view_, c, limit * limit) : cell_diverged<false>(view_, c, limit * limit);
      if (bad) first = std::min<long long>(first, c);
    }
    return first == std::numeric_limits<long long>::max() ? -1 : first;
  }

 private:
  PopulationBuffer g_;
  std::vector<float> force_, aux_, bnd_value_;
  // Per bulk segment: 1 where a cell of it may hold a non-zero field force (set when one is set,
  // cleared only by set_force_field), so that segments without one skip the field.
  std::vector<std::uint8_t> segment_forced_;
  // The cells of the last listed-cell force call and the bulk segment of each (-1: none): the LRM
  // lists the same disk cells every step, and looking their segments up each time cost as much as
  // evaluating the forces (2026-12-04). Cleared where the segments change (mark_forced_segments).
  std::vector<std::uint32_t> listed_cells_;
  std::vector<std::int64_t> listed_segment_;
  // update_segment's group of cells, and the lanes its last cells are copied into: the AVX-512
  // registers' 16 floats where the compiler targets them, else 8 (an AVX2 register, two SSE ones).
  // The rest of a segment costs a whole group's arithmetic, so a wider group than the registers only
  // wastes lanes (the LRM's 38-cell rows: 6 cells in 16 lanes took a fifth of the N = 32 step on an
  // AVX2 machine).
#if defined(__AVX512F__)
  static constexpr std::size_t kLanes = 16;
#else
  static constexpr std::size_t kLanes = 8;
#endif
  // run_step's loops (segments, general cells, boundary states, boundary blocks, held cells, absorbing cells) and their
  // chunks (a few dozen per thread's share at N = 32)
  static constexpr long kSegmentChunk = 16, kGeneralChunk = 32, kBoundaryChunk = 128, kBlockChunk = 2, kHeldChunk = 32;
  TeamLoop loops_[6];
};

}  // namespace

std::unique_ptr<Solver> make_cpu_solver(Lattice lattice) { return std::make_unique<CpuSolver>(std::move(lattice)); }

}  // namespace ship_lrm::lbm
