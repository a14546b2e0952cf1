// The ship-wake table's reader (see wake_table.hpp): windows of two frames around a box, read ahead,
// and the trilinear-in-space, linear-in-time interpolation, over a WindowSource (the HDF5 file:
// wake_table_hdf5.cpp; or another process).
#include "ship_lrm/wake/wake_table.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <future>

namespace ship_lrm::wake {

struct WakeTable::ReadAhead {
  std::future<bool> done;
  Window w;
  int frame = -1;
};

WakeTable::WakeTable(const std::string& path, std::size_t window_points) : max_points_(window_points) {
  source_ = open_table_file(path, info_);
  check_info();
}

WakeTable::WakeTable(const WakeTableInfo& info, std::unique_ptr<WindowSource> source, std::size_t window_points)
    : source_(std::move(source)), info_(info), max_points_(window_points) {
  if (!source_) throw TableError("wake table: no source of windows");
  check_info();
}

void WakeTable::check_info() const {
  if (!(info_.spacing > 0) || !(info_.frame_interval > 0) || info_.shape[0] < 2 || info_.shape[1] < 2 || info_.shape[2] < 2)
    throw TableError(source_->name() + ": invalid grid or frame interval attributes");
  if (info_.frames < 1) throw TableError(source_->name() + " holds no frames");
  for (double v : {info_.origin[0], info_.origin[1], info_.origin[2], info_.free_stream[0], info_.free_stream[1], info_.free_stream[2],
                   info_.start_time, info_.free_density})
    if (!std::isfinite(v)) throw TableError(source_->name() + ": its grid or free stream is not finite");
}

WakeTable::~WakeTable() {
  if (ahead_ && ahead_->done.valid()) ahead_->done.wait();  // the read-ahead thread uses source_
}

void WakeTable::read_box(int frame, const std::array<int, 3>& lo, const std::array<int, 3>& n, std::vector<float>& velocity,
                         std::vector<float>& density) const {
  if (frame < 0 || frame >= info_.frames)
    throw TableError(source_->name() + ": frame " + std::to_string(frame) + " out of range [0, " + std::to_string(info_.frames) + ")");
  for (int d = 0; d < 3; ++d)
    if (lo[d] < 0 || n[d] < 1 || lo[d] + n[d] > info_.shape[d])
      throw TableError(source_->name() + ": the box asked for lies outside the grid");
  const std::size_t pts = static_cast<std::size_t>(n[0]) * n[1] * n[2];
  velocity.resize(3 * pts);
  density.resize(pts);
  if (!source_->read(frame, lo, n, velocity.data(), density.data()))
    throw TableError(source_->name() + ": frame " + std::to_string(frame) + " is unreadable (corrupt or truncated file)");
}

void WakeTable::read_frame(int frame, std::vector<float>& velocity, std::vector<float>& density) const {
  constexpr std::size_t kMaxFramePoints = std::size_t(1) << 26;  // 1 GB of float32 values
  if (info_.points() > kMaxFramePoints)
    throw TableError(source_->name() + ": a whole frame of its served grid has " + std::to_string(info_.points()) +
                     " points; read boxes of it (read_box)");
  read_box(frame, {0, 0, 0}, info_.shape, velocity, density);
}

namespace {
bool covers_box(const std::array<int, 3>& wlo, const std::array<int, 3>& wn, const std::array<int, 3>& lo, const std::array<int, 3>& hi) {
  for (int d = 0; d < 3; ++d)
    if (wlo[d] > lo[d] || wlo[d] + wn[d] <= hi[d]) return false;
  return true;
}
std::uint64_t next_window_serial() {
  static std::atomic<std::uint64_t> serials{0};
  return ++serials;
}
}  // namespace

bool WakeTable::load(Window& w, int frame, const std::array<int, 3>& a, const std::array<int, 3>& n) const {
  const std::size_t pts = static_cast<std::size_t>(n[0]) * n[1] * n[2];
  w.u.resize(3 * pts);
  w.rho.resize(pts);
  return source_->read(frame, a, n, w.u.data(), w.rho.data());
}

void WakeTable::read_ahead(int frame, const Window& like) {
  if (frame >= info_.frames || like.frame < 0) return;
  if (ahead_ && ahead_->frame == frame) return;  // on its way or waiting
  if (w_[frame % 2].frame == frame && w_[frame % 2].lo == like.lo && w_[frame % 2].n == like.n) return;
  if (!ahead_) ahead_ = std::make_unique<ReadAhead>();
  if (ahead_->done.valid()) ahead_->done.wait();  // an older read-ahead that was not used
  ahead_->frame = frame;
  ahead_->w.frame = frame;
  ahead_->w.lo = like.lo;
  ahead_->w.n = like.n;
  ReadAhead* r = ahead_.get();
  r->done = std::async(std::launch::async, [this, r] { return load(r->w, r->frame, r->w.lo, r->w.n); });
}

const WakeTable::Window& WakeTable::window(int frame, const std::array<int, 3>& lo, const std::array<int, 3>& hi) {
  // consecutive frames alternate between the two slots, so the two frames of one sample never evict
  // each other
  Window& w = w_[frame % 2];
  if (w.frame == frame && covers_box(w.lo, w.n, lo, hi)) return w;
  if (ahead_ && ahead_->frame == frame) {  // read ahead: wait for it (usually long done) and take it
    const bool ok = ahead_->done.get();
    ahead_->frame = -1;
    if (ok && covers_box(ahead_->w.lo, ahead_->w.n, lo, hi)) {
      std::swap(w, ahead_->w);
      w.serial = next_window_serial();
      ++loads_;
      ++read_ahead_hits_;
      return w;
    }
  }
  // load a window around [lo, hi] with a margin of a quarter of its size (the domain moves on: a
  // window serves up to three frame intervals, the read-ahead's included), bounded by max_points_
  std::array<int, 3> a{}, n{};
  std::size_t need = 1, with_margin = 1;
  for (int d = 0; d < 3; ++d) {
    need *= static_cast<std::size_t>(hi[d] - lo[d] + 1);
    const int margin = (hi[d] - lo[d] + 1) / 4 + 1;
    a[d] = std::max(0, lo[d] - margin);
    n[d] = std::min(info_.shape[d] - 1, hi[d] + margin) - a[d] + 1;
    with_margin *= static_cast<std::size_t>(n[d]);
  }
  if (need > max_points_)
    throw TableError("wake table: the requested region (" + std::to_string(need) + " grid points) exceeds the window limit of " +
                     std::to_string(max_points_) + " points");
  if (with_margin > max_points_)
    for (int d = 0; d < 3; ++d) {
      a[d] = lo[d];
      n[d] = hi[d] - lo[d] + 1;
    }
  if (!load(w, frame, a, n)) {
    w.frame = -1;
    throw TableError(source_->name() + ": frame " + std::to_string(frame) + " is unreadable (corrupt or truncated file)");
  }
  w.frame = frame;
  w.lo = a;
  w.n = n;
  w.serial = next_window_serial();
  ++loads_;
  return w;
}

namespace {
// Time of a sample as the frames around it and the weight of the second (clamped to the table).
void frame_pair(const WakeTableInfo& info, double t, int& f0, int& f1, double& weight1) {
  double ft = (t - info.start_time) / info.frame_interval;
  ft = std::clamp(ft, 0.0, static_cast<double>(info.frames - 1));
  f0 = std::min(static_cast<int>(ft), info.frames - 1);
  f1 = std::min(f0 + 1, info.frames - 1);
  weight1 = ft - f0;
}
}  // namespace

WakeTable::Frames WakeTable::frames(double t, const std::array<double, 3>& lo_m, const std::array<double, 3>& hi_m) {
  if (!std::isfinite(t)) throw TableError("wake table: sample time is not finite");
  Frames r;
  for (int d = 0; d < 3; ++d) {
    if (!std::isfinite(lo_m[d]) || !std::isfinite(hi_m[d]) || lo_m[d] > hi_m[d])
      throw TableError("wake table: the box to feed is not valid");
    r.grid.origin[d] = info_.origin[d];
    r.grid.shape[d] = info_.shape[d];
    r.grid.free_stream[d] = static_cast<float>(info_.free_stream[d]);
  }
  r.grid.spacing = info_.spacing;
  int f0, f1;
  frame_pair(info_, t, f0, f1, r.grid.weight1);
  // the grid cells the box touches, clipped to the table (a box that misses it: empty windows)
  std::array<int, 3> lo{}, hi{};
  for (int d = 0; d < 3; ++d) {
    const double a = (lo_m[d] - info_.origin[d]) / info_.spacing, b = (hi_m[d] - info_.origin[d]) / info_.spacing;
    if (b < 0.0 || a > info_.shape[d] - 1) return r;
    lo[d] = std::clamp(static_cast<int>(std::floor(a)), 0, info_.shape[d] - 2);
    hi[d] = std::clamp(static_cast<int>(std::floor(b)) + 1, 1, info_.shape[d] - 1);
  }
  const int fr[2] = {f0, f1};
  for (int s = 0; s < 2; ++s) {
    const Window& w = window(fr[s], lo, hi);
    for (int d = 0; d < 3; ++d) {
      r.window[s].lo[d] = w.lo[d];
      r.window[s].n[d] = w.n[d];
    }
    r.window[s].u = w.u.data();
    r.serial[s] = w.serial;
  }
  read_ahead(f1 + 1, w_[f1 % 2]);
  return r;
}

void WakeTable::sample(double t, const std::vector<double>& xyz, std::vector<WakeSample>& out) {
  const std::size_t np = xyz.size() / 3;
  out.resize(np);
  if (!std::isfinite(t)) throw TableError("wake table: sample time is not finite");
  // grid coordinates and the box of the points inside the table
  std::array<int, 3> lo{info_.shape[0], info_.shape[1], info_.shape[2]}, hi{-1, -1, -1};
  std::vector<double> g(xyz.size());
  std::vector<char> in(np);
  const long npl = static_cast<long>(np);
  // Every point is independent: the loops over points run on the OpenMP threads (the LRM's faces
  // have 10^4 - 10^5 points, sampled whenever they are due).
#pragma omp parallel for schedule(static)
  for (long p = 0; p < npl; ++p) {
    for (int d = 0; d < 3; ++d) g[3 * p + d] = (xyz[3 * p + d] - info_.origin[d]) / info_.spacing;
    in[p] = lbm::grid_inside(&g[3 * p], info_.shape.data());
  }
  for (std::size_t p = 0; p < np; ++p) {
    if (!in[p]) continue;
    int i[3];
    double fr[3];
    lbm::grid_cell(&g[3 * p], info_.shape.data(), i, fr);
    for (int d = 0; d < 3; ++d) {
      lo[d] = std::min(lo[d], i[d]);
      hi[d] = std::max(hi[d], i[d] + 1);
    }
  }
  const WakeSample free{
      {static_cast<float>(info_.free_stream[0]), static_cast<float>(info_.free_stream[1]), static_cast<float>(info_.free_stream[2])},
      static_cast<float>(info_.free_density)};
  if (hi[0] < 0) {
    std::fill(out.begin(), out.end(), free);
    return;
  }
  int f0, f1;
  double at;
  frame_pair(info_, t, f0, f1, at);
  const Window* w[2] = {&window(f0, lo, hi), &window(f1, lo, hi)};
#pragma omp parallel for schedule(static)
  for (long p = 0; p < npl; ++p) {
    if (!in[p]) {
      out[p] = free;
      continue;
    }
    double acc[4] = {0, 0, 0, 0};
    int i[3];
    double fr[3];
    lbm::grid_cell(&g[3 * p], info_.shape.data(), i, fr);
    for (int s = 0; s < 2; ++s) {  // the same interpolation as the LRM's face feed (grid_feed.hpp)
      const Window& W = *w[s];
      const double wt = s == 0 ? 1.0 - at : at;
      if (wt == 0.0) continue;
      lbm::accumulate_trilinear(W.u.data(), 3, W.lo.data(), W.n.data(), i, fr, wt, acc);
      lbm::accumulate_trilinear(W.rho.data(), 1, W.lo.data(), W.n.data(), i, fr, wt, acc + 3);
    }
    out[p] = {{static_cast<float>(acc[0]), static_cast<float>(acc[1]), static_cast<float>(acc[2])}, static_cast<float>(acc[3])};
  }
  read_ahead(f1 + 1, *w[1]);
}

}  // namespace ship_lrm::wake
