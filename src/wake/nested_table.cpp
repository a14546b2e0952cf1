// A nested wake table's levels served as one grid (see nested_table.hpp).
#include "ship_lrm/wake/nested_table.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>
#include <vector>

#include "ship_lrm/lbm/grid_feed.hpp"

namespace ship_lrm::wake {
namespace {

constexpr int kMaxLevelRatio = 16;

std::array<int, 3> fine_origin(const WakeTableInfo& stored) {
  const int r = stored.fine.ratio;
  return {stored.fine.lo[0] * r, stored.fine.lo[1] * r, stored.fine.lo[2] * r};
}

// fine_weight's part from axis d at served index v: the served cells to the nearest blended face of
// the fine box along d (infinity with none), -1 outside the box along d.
double axis_nearest(const WakeTableInfo& stored, const std::array<int, 3>& f0, int d, int v) {
  const WakeTableLevel& f = stored.fine;
  const int below = v - f0[d], above = f0[d] + f.shape[d] - 1 - v;
  if (below < 0 || above < 0) return -1.0;
  double nearest = std::numeric_limits<double>::infinity();
  if (f.seam[2 * d]) nearest = std::min(nearest, static_cast<double>(below));
  if (f.seam[2 * d + 1]) nearest = std::min(nearest, static_cast<double>(above));
  return nearest;
}

// The fine weight from the smallest of the axes' parts.
double weight_from_nearest(const WakeTableInfo& stored, double nearest) {
  if (nearest < 0.0) return 0.0;
  const double band = stored.fine.seam_cells * stored.fine.ratio;
  return band > 0.0 ? std::min(1.0, nearest / band) : 1.0;
}

class NestedWindowSource final : public WindowSource {
 public:
  NestedWindowSource(std::unique_ptr<LevelSource> levels, const WakeTableInfo& stored) : levels_(std::move(levels)), stored_(stored) {}

  bool read(int frame, const std::array<int, 3>& lo, const std::array<int, 3>& n, float* velocity, float* density) override {
    const std::lock_guard<std::mutex> lock(mutex_);  // the table's read-ahead thread may read at the same time
    const int r = stored_.fine.ratio;
    const std::array<int, 3>& cs = stored_.shape;
    // the coarse cells under the box (grid_cell's convention: the last point belongs to the cell before it)
    std::array<int, 3> clo{}, cn{};
    for (int d = 0; d < 3; ++d) {
      const int a = std::min(lo[d] / r, cs[d] - 2), b = std::min((lo[d] + n[d] - 1) / r, cs[d] - 2) + 1;
      clo[d] = a;
      cn[d] = b - a + 1;
    }
    std::vector<float>& cu = coarse_u_;
    std::vector<float>& cr = coarse_rho_;
    const std::size_t cpts = static_cast<std::size_t>(cn[0]) * cn[1] * cn[2];
    cu.resize(3 * cpts);
    cr.resize(cpts);
    if (!levels_->read(0, frame, clo, cn, cu.data(), cr.data())) return false;
    // the fine points in the box
    const std::array<int, 3> f0 = fine_origin(stored_);
    std::array<int, 3> flo{}, fn{};
    bool fine = true;
    for (int d = 0; d < 3; ++d) {
      const int a = std::max(lo[d], f0[d]), b = std::min(lo[d] + n[d] - 1, f0[d] + stored_.fine.shape[d] - 1);
      flo[d] = a - f0[d];
      fn[d] = b - a + 1;
      fine = fine && fn[d] > 0;
    }
    if (fine) {
      const std::size_t fpts = static_cast<std::size_t>(fn[0]) * fn[1] * fn[2];
      fine_u_.resize(3 * fpts);
      fine_rho_.resize(fpts);
      if (!levels_->read(1, frame, flo, fn, fine_u_.data(), fine_rho_.data())) return false;
    }
    // per axis, once for the box: the coarse cell and fraction under each served point, and the fine
    // weight's part from that axis (fine_weight, separated: the nearest blended face along it)
    for (int d = 0; d < 3; ++d) {
      Axis& ax = axes_[d];
      ax.cell.resize(n[d]);
      ax.frac.resize(n[d]);
      ax.nearest.resize(n[d]);
      for (int k = 0; k < n[d]; ++k) {
        const int v = lo[d] + k;
        const double g = static_cast<double>(v) / r, g3[3] = {g, g, g};
        const int s3[3] = {cs[d], cs[d], cs[d]};
        int i3[3];
        double f3[3];
        lbm::grid_cell(g3, s3, i3, f3);  // one axis of it
        ax.cell[k] = i3[0];
        ax.frac[k] = f3[0];
        ax.nearest[k] = axis_nearest(stored_, f0, d, v);
      }
    }
    const long planes = n[2];
#pragma omp parallel for schedule(static)
    for (long kz = 0; kz < planes; ++kz)
      for (int ky = 0; ky < n[1]; ++ky)
        for (int kx = 0; kx < n[0]; ++kx) {
          const int k[3] = {kx, ky, static_cast<int>(kz)};
          const std::size_t p = kx + static_cast<std::size_t>(n[0]) * (ky + static_cast<std::size_t>(n[1]) * kz);
          int i[3];
          double fr[3], acc[4] = {0, 0, 0, 0}, nearest = std::numeric_limits<double>::infinity();
          for (int d = 0; d < 3; ++d) {
            i[d] = axes_[d].cell[k[d]];
            fr[d] = axes_[d].frac[k[d]];
            nearest = std::min(nearest, axes_[d].nearest[k[d]]);
          }
          lbm::accumulate_trilinear(cu.data(), 3, clo.data(), cn.data(), i, fr, 1.0, acc);
          lbm::accumulate_trilinear(cr.data(), 1, clo.data(), cn.data(), i, fr, 1.0, acc + 3);
          // fine_weight(stored_, v) from the axes' parts
          const double w = fine ? weight_from_nearest(stored_, nearest) : 0.0;
          if (w > 0.0) {
            const std::size_t q = (lo[0] + kx - f0[0] - flo[0]) +
                                  static_cast<std::size_t>(fn[0]) *
                                      ((lo[1] + ky - f0[1] - flo[1]) + static_cast<std::size_t>(fn[1]) * (lo[2] + k[2] - f0[2] - flo[2]));
            for (int a = 0; a < 3; ++a) acc[a] = w >= 1.0 ? fine_u_[3 * q + a] : acc[a] + w * (fine_u_[3 * q + a] - acc[a]);
            acc[3] = w >= 1.0 ? fine_rho_[q] : acc[3] + w * (fine_rho_[q] - acc[3]);
          }
          for (int a = 0; a < 3; ++a) velocity[3 * p + a] = static_cast<float>(acc[a]);
          density[p] = static_cast<float>(acc[3]);
        }
    return true;
  }

  std::string name() const override { return levels_->name(); }

 private:
  std::unique_ptr<LevelSource> levels_;
  WakeTableInfo stored_;
  std::mutex mutex_;  // one read at a time through the buffers
  std::vector<float> coarse_u_, coarse_rho_, fine_u_, fine_rho_;
  struct Axis {
    std::vector<int> cell;
    std::vector<double> frac, nearest;  // nearest: -1 outside the fine box, infinity with no blended face
  };
  std::array<Axis, 3> axes_;
};

}  // namespace

void check_levels(const WakeTableInfo& stored, const std::string& name) {
  const WakeTableLevel& f = stored.fine;
  if (f.ratio == 0) return;
  if (f.ratio < 1 || f.ratio > kMaxLevelRatio)
    throw TableError(name + ": its fine level's ratio " + std::to_string(f.ratio) + " is not 1 .. " + std::to_string(kMaxLevelRatio));
  for (int d = 0; d < 3; ++d) {
    const int cells = (f.shape[d] - 1) / f.ratio;
    if (f.shape[d] < 2 || (f.shape[d] - 1) % f.ratio != 0)
      throw TableError(name + ": its fine level's shape does not refine whole coarse cells (" + std::to_string(f.shape[d]) +
                       " points at ratio " + std::to_string(f.ratio) + ")");
    if (f.lo[d] < 0 || f.lo[d] + cells > stored.shape[d] - 1)
      throw TableError(name + ": its fine level does not lie inside the coarse grid");
  }
  for (int s : f.seam)
    if (s != 0 && s != 1) throw TableError(name + ": its fine level's seam flags are not 0 or 1");
  if (!(f.seam_cells >= 0) || !std::isfinite(f.seam_cells)) throw TableError(name + ": its fine level's seam width is not >= 0");
}

WakeTableInfo served_grid(const WakeTableInfo& stored) {
  WakeTableInfo s = stored;
  const int r = stored.fine.ratio;
  if (r <= 1) return s;
  s.spacing = stored.spacing / r;
  for (int d = 0; d < 3; ++d) s.shape[d] = (stored.shape[d] - 1) * r + 1;
  return s;
}

double fine_weight(const WakeTableInfo& stored, const std::array<int, 3>& v) {
  if (stored.fine.ratio < 1) return 0.0;
  const std::array<int, 3> f0 = fine_origin(stored);
  double nearest = std::numeric_limits<double>::infinity();
  for (int d = 0; d < 3; ++d) {
    const double n = axis_nearest(stored, f0, d, v[d]);
    if (n < 0.0) return 0.0;
    nearest = std::min(nearest, n);
  }
  return weight_from_nearest(stored, nearest);
}

std::unique_ptr<WindowSource> nested_window_source(std::unique_ptr<LevelSource> levels, const WakeTableInfo& stored) {
  check_levels(stored, levels->name());
  return std::make_unique<NestedWindowSource>(std::move(levels), stored);
}

}  // namespace ship_lrm::wake
