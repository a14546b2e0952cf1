// CPU backend: OpenMP over the cell lists of the Lattice, per-cell physics from lattice_view.hpp.
#include <sys/mman.h>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <memory>

#include "ship_lrm/lbm/solver.hpp"

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
      force_.resize(3 * n);
      for (std::size_t c = 0; c < n; ++c)
        for (int a = 0; a < 3; ++a) {
          if (!std::isfinite(f[3 * c + a])) throw ConfigError("set_force_field: force is not finite");
          force_[a * n + c] = f[3 * c + a];
        }
    }
    sync_view();
  }

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
  }

  void do_initialize(const std::vector<float>& rho, const std::vector<float>& u) override {
    const std::size_t n = lattice_.cells();
    const LatticeView& v = view_;
#pragma omp parallel for schedule(static)
    for (std::size_t c = 0; c < n; ++c) {
      Macro m;
      if (!rho.empty()) m.rho = rho[c];
      if (!u.empty())
        for (int a = 0; a < 3; ++a) m.u[a] = u[3 * c + a];
      for (int i = 0; i < Q; ++i) pop(v, i, c) = store_pop(equilibrium(i, m.rho, m.u));
      if (v.aux) store_aux(v, c, m);
    }
    for (int b = 0; b < v.nbnd; ++b) initialize_boundary_state(v, b);  // prescribed start state
  }

  template <bool kOdd, bool kSmagorinsky, int kForce>
  void run_step() {
    const LatticeView& v = view_;
    const auto& support = lattice_.support_cells();
    const auto& support_b = lattice_.support_boundary_index();
    const auto& support_m = lattice_.support_link_masks();
    const auto& segs = lattice_.bulk_segments();
    const auto& general = lattice_.general_cells();
    const auto& masks = lattice_.general_link_masks();
    const long ns = static_cast<long>(support.size()), nseg = static_cast<long>(segs.size()), ng = static_cast<long>(general.size());
#pragma omp parallel
    {
#pragma omp for schedule(static)
      for (long k = 0; k < ns; ++k) update_support_macro<kOdd>(v, support[k], support_b[k], support_m[k]);
        // implicit barrier: every support state is known before any population is overwritten
#pragma omp for schedule(static) nowait
      for (long s = 0; s < nseg; ++s) {
        const Segment& sg = segs[s];
        const std::int64_t* off = v.row_offsets + Q * sg.cell_class;
        const std::size_t first = sg.first, last = first + sg.count;
        if (sg.link_mask == 0) {  // bulk: neighbours at fixed offsets (fewer live pointers)
#pragma omp simd
          for (std::size_t c = first; c < last; ++c) update_bulk_cell<kOdd, kSmagorinsky, kForce>(v, c, off);
        } else {
          pop_t* src[Q];
          pop_t* dst[Q];
          segment_addresses<kOdd>(v, sg.link_mask, sg.reflection, off, src, dst);
#pragma omp simd
          for (std::size_t c = first; c < last; ++c) update_segment_cell<kSmagorinsky, kForce>(v, c, src, dst);
        }
      }
#pragma omp for schedule(static) nowait
      for (long k = 0; k < ng; ++k) update_wall_cell<kOdd>(v, general[k], masks[k]);
#pragma omp for schedule(static)
      for (int b = 0; b < v.nbnd; ++b) update_boundary_cell<kOdd>(v, b);
    }
  }

  template <bool kOdd, bool kSmagorinsky>
  void run_step_forced() {
    switch (force_mode(view_)) {
      case kNoForce:
        return run_step<kOdd, kSmagorinsky, kNoForce>();
      case kUniformForce:
        return run_step<kOdd, kSmagorinsky, kUniformForce>();
      case kForceField:
        return run_step<kOdd, kSmagorinsky, kForceField>();
      default:
        return run_step<kOdd, kSmagorinsky, kFrameForce>();
    }
  }
  template <bool kOdd>
  void run_step_dispatch() {
    view_.params.smagorinsky > 0.0f ? run_step_forced<kOdd, true>() : run_step_forced<kOdd, false>();
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
    for (std::size_t k = 0; k < cells.size(); ++k)
      for (int a = 0; a < 3; ++a) force_[a * n + cells[k]] = f[3 * k + a];
  }

  void do_fields(bool next_odd, Fields& out) override {
    const long n = static_cast<long>(lattice_.cells());
#pragma omp parallel for schedule(static)
    for (long c = 0; c < n; ++c) {
      const Macro m = next_odd ? macro_at<true>(c) : macro_at<false>(c);
      out.rho[c] = m.rho;
      for (int a = 0; a < 3; ++a) out.u[3 * c + a] = m.u[a];
    }
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
};

}  // namespace

std::unique_ptr<Solver> make_cpu_solver(Lattice lattice) { return std::make_unique<CpuSolver>(std::move(lattice)); }

}  // namespace ship_lrm::lbm
