// CUDA backend: the same per-cell functions as the CPU backend (lattice_view.hpp), one thread per
// cell. Populations, cell types and boundary data live on the device; the host keeps the view.
#include <cuda_runtime.h>

#include <algorithm>
#include <cstring>
#include <sstream>

#include "ship_lrm/lbm/benchmark.hpp"
#include "ship_lrm/lbm/column_series.hpp"
#include "ship_lrm/lbm/solver.hpp"

namespace ship_lrm::lbm {
namespace {

void check(cudaError_t e, const char* what) {
  if (e != cudaSuccess) {
    std::ostringstream s;
    s << "CUDA error in " << what << ": " << cudaGetErrorString(e);
    throw std::runtime_error(s.str());
  }
}

template <typename T>
class DeviceArray {
 public:
  DeviceArray() = default;
  explicit DeviceArray(std::size_t n) { resize(n); }
  ~DeviceArray() { cudaFree(p_); }
  DeviceArray(const DeviceArray&) = delete;
  DeviceArray& operator=(const DeviceArray&) = delete;
  void resize(std::size_t n) {
    cudaFree(p_);
    p_ = nullptr;
    n_ = n;
    if (n) check(cudaMalloc(&p_, n * sizeof(T)), "cudaMalloc");
  }
  void upload(const std::vector<T>& h) {
    if (h.size() != n_) resize(h.size());
    if (n_) check(cudaMemcpy(p_, h.data(), n_ * sizeof(T), cudaMemcpyHostToDevice), "upload");
  }
  void download(std::vector<T>& h) const {
    h.resize(n_);
    if (n_) check(cudaMemcpy(h.data(), p_, n_ * sizeof(T), cudaMemcpyDeviceToHost), "download");
  }
  T* data() const { return p_; }
  std::size_t size() const { return n_; }

 private:
  T* p_ = nullptr;
  std::size_t n_ = 0;
};

constexpr int kBlock = 128;
unsigned blocks(std::size_t n) { return static_cast<unsigned>((n + kBlock - 1) / kBlock); }

// Pass 0 over every cell. (A split that ran the open-boundary passes on a second stream beside the
// interior was measured slower on the H100: docs/benchmarks.md at 193c1b4, 2026-11-24.)
template <bool kOdd, int kCollision, int kForce>
__global__ void fluid_kernel(LatticeView v, const std::uint32_t* __restrict__ masks) {
  const std::size_t c = static_cast<std::size_t>(blockIdx.x) * blockDim.x + threadIdx.x;
  if (c >= v.ncells) return;
  const std::uint8_t t = v.type[c];
  if (t == static_cast<std::uint8_t>(CellType::Fluid)) {
    int x, y, z;
    cell_coords(v, c, x, y, z);
    const std::int64_t* off = v.row_offsets + Q * cell_class(v.n, x, y, z);
    const float px = static_cast<float>(x), py = static_cast<float>(y), pz = static_cast<float>(z);
    // With open boundaries every fluid cell stores its state (aux): a flag per cell would cost
    // about as much as the 16 bytes (the CPU backend stores only its support cells').
    if (v.aux)
      update_bulk_cell<kOdd, kCollision, kForce, true>(v, c, px, py, pz, off);
    else
      update_bulk_cell<kOdd, kCollision, kForce, false>(v, c, px, py, pz, off);
  } else if (t == (static_cast<std::uint8_t>(CellType::Fluid) | kGeneralBit)) {
    update_wall_cell<kOdd>(v, c, masks[c]);
  }
}

template <bool kOdd>
__global__ void boundary_state_kernel(LatticeView v) {
  const int b = blockIdx.x * blockDim.x + threadIdx.x;
  if (b < v.nbnd) update_boundary_state<kOdd>(v, b);
}

template <bool kOdd, int kCollision, int kForce>
__global__ void boundary_kernel(LatticeView v) {
  const int b = blockIdx.x * blockDim.x + threadIdx.x;
  if (b < v.nbnd) update_boundary_cell<kOdd, kCollision, kForce>(v, b);
}

template <bool kOdd>
__device__ Macro device_macro(const LatticeView& v, std::size_t c) {
  if (is_wall(static_cast<CellType>(v.type[c] & ~kGeneralBit))) return Macro{};
  return cell_macro<kOdd>(v, c);
}

template <bool kOdd>
__global__ void fields_kernel(LatticeView v, float* rho, float* u) {
  const std::size_t c = static_cast<std::size_t>(blockIdx.x) * blockDim.x + threadIdx.x;
  if (c >= v.ncells) return;
  const Macro m = device_macro<kOdd>(v, c);
  rho[c] = m.rho;
  for (int a = 0; a < 3; ++a) u[3 * c + a] = m.u[a];
}

// Velocity at listed cells (the LRM's rotor-disk cells), so that only those cross to the host.
template <bool kOdd>
__global__ void gather_velocity_kernel(LatticeView v, const std::uint32_t* cells, std::size_t n, float* u) {
  const std::size_t k = static_cast<std::size_t>(blockIdx.x) * blockDim.x + threadIdx.x;
  if (k >= n) return;
  const Macro m = device_macro<kOdd>(v, cells[k]);
  for (int a = 0; a < 3; ++a) u[3 * k + a] = m.u[a];
}

// Force density at listed cells into the structure-of-arrays force field (ncells per component).
__global__ void scatter_force_kernel(float* force, std::size_t ncells, const std::uint32_t* cells, std::size_t n, const float* f) {
  const std::size_t k = static_cast<std::size_t>(blockIdx.x) * blockDim.x + threadIdx.x;
  if (k >= n) return;
  for (int a = 0; a < 3; ++a) force[a * ncells + cells[k]] = f[3 * k + a];
}

// The columns' coefficients as a kernel argument (Solver::set_cell_force_coefficients): they cross
// the bus with the launch, no copy of their own.
struct ColumnCoefficients {
  float c[3 * kMaxForceColumns];
};

// Force density at listed cell k as the sum of its columns (column_series.hpp, the host's sum).
__global__ void column_force_kernel(float* force, std::size_t ncells, const std::uint32_t* cells, std::size_t n, const float* basis,
                                    int columns, ColumnCoefficients coefficients) {
  const std::size_t k = static_cast<std::size_t>(blockIdx.x) * blockDim.x + threadIdx.x;
  if (k >= n) return;
  float f[3];
  column_series(basis, n, k, k + 1, columns, coefficients.c, f, 1);
  for (int a = 0; a < 3; ++a) force[a * ncells + cells[k]] = f[a];
}

template <bool kOdd>
__global__ void divergence_kernel(LatticeView v, float limit2, unsigned long long* first) {
  const std::size_t c = static_cast<std::size_t>(blockIdx.x) * blockDim.x + threadIdx.x;
  if (c >= v.ncells) return;
  if (cell_diverged<kOdd>(v, c, limit2)) atomicMin(first, static_cast<unsigned long long>(c));
}

__global__ void init_kernel(LatticeView v, const float* rho, const float* u) {
  const std::size_t c = static_cast<std::size_t>(blockIdx.x) * blockDim.x + threadIdx.x;
  if (c >= v.ncells) return;
  Macro m;
  if (rho) m.rho = rho[c];
  if (u)
    for (int a = 0; a < 3; ++a) m.u[a] = u[3 * c + a];
  set_cell_equilibrium<false>(v, c, m);
  if (v.aux) store_aux(v, c, m);
}

// The held cells after a step (hold_cell in lattice_view.hpp).
template <bool kOddDone>
__global__ void hold_kernel(LatticeView v) {
  const int h = blockIdx.x * blockDim.x + threadIdx.x;
  if (h < v.nheld) hold_cell<kOddDone>(v, h);
}

// The absorbing layers' cells after a step (absorb_cell in lattice_view.hpp).
template <bool kOddDone>
__global__ void absorb_kernel(LatticeView v) {
  const int a = blockIdx.x * blockDim.x + threadIdx.x;
  if (a < v.nabsorbing) absorb_cell<kOddDone>(v, a);
}

__global__ void init_boundary_kernel(LatticeView v) {
  const int b = blockIdx.x * blockDim.x + threadIdx.x;
  if (b >= v.nbnd) return;
  initialize_boundary_state(v, b);
}

// The velocity faces from a gridded field (grid_feed.hpp): the same per-cell functions as LrmDomain's
// host path and Solver::feed_faces_from_grid's. Velocity inlets take the face velocity, impedance outlets take it as their reference and
// its normal change (Solver::set_boundary_values). The largest face speed goes to *fastest (the bits
// of a non-negative float order as the float). values: the view's boundary values, writable.
__global__ void grid_feed_kernel(LatticeView v, float* values, GridFeed f, GridWindowView w0, GridWindowView w1, unsigned* fastest) {
  const int b = blockIdx.x * blockDim.x + threadIdx.x;
  if (b >= v.nbnd) return;
  const std::uint32_t c = v.bnd_cell[b];
  const auto t = static_cast<CellType>(v.type[c] & ~kGeneralBit);
  if (t != CellType::VelocityInlet && t != CellType::ImpedanceOutlet) return;
  int x, y, z;
  cell_coords(v, c, x, y, z);
  float* value = values + 4 * b;
  feed_boundary_cell(f, w0, w1, t == CellType::ImpedanceOutlet, v.bnd_normal[b], x, y, z, value);
  const float speed = sqrtf(value[0] * value[0] + value[1] * value[1] + value[2] * value[2]);
  atomicMax(fastest, isfinite(speed) ? __float_as_uint(speed) : 0x7f800000u);
}

// The reference change has been stepped: zero the 4th value of every impedance outlet.
__global__ void clear_reference_change_kernel(LatticeView v, float* values) {
  const int b = blockIdx.x * blockDim.x + threadIdx.x;
  if (b >= v.nbnd) return;
  if (static_cast<CellType>(v.type[v.bnd_cell[b]] & ~kGeneralBit) == CellType::ImpedanceOutlet) values[4 * b + 3] = 0.0f;
}

__global__ void copy_kernel(const float4* __restrict__ a, float4* __restrict__ b, std::size_t n) {
  for (std::size_t i = static_cast<std::size_t>(blockIdx.x) * blockDim.x + threadIdx.x; i < n;
       i += static_cast<std::size_t>(gridDim.x) * blockDim.x)
    b[i] = a[i];
}

__global__ void inplace_kernel(float4* __restrict__ a, std::size_t n) {
  for (std::size_t i = static_cast<std::size_t>(blockIdx.x) * blockDim.x + threadIdx.x; i < n;
       i += static_cast<std::size_t>(gridDim.x) * blockDim.x) {
    float4 v = a[i];
    v.x *= 1.0001f, v.y *= 1.0001f, v.z *= 1.0001f, v.w *= 1.0001f;
    a[i] = v;
  }
}

// Link mask of every cell (0 for bulk cells), from the Lattice's segments and general cells.
std::vector<std::uint32_t> full_link_masks(const Lattice& lat) {
  std::vector<std::uint32_t> m(lat.cells(), 0);
  for (const Segment& sg : lat.bulk_segments())
    for (std::uint32_t k = 0; k < sg.count; ++k) m[sg.first + k] = sg.link_mask;
  for (std::size_t k = 0; k < lat.general_cells().size(); ++k) m[lat.general_cells()[k]] = lat.general_link_masks()[k];
  return m;
}

class CudaSolver final : public Solver {
 public:
  explicit CudaSolver(Lattice lattice) : Solver(std::move(lattice)) {
    int count = 0;
    if (cudaGetDeviceCount(&count) != cudaSuccess || count == 0) {
      cudaGetLastError();
      throw ConfigError("backend 'cuda' requested, but no CUDA device is available");
    }
    const std::size_t n = lattice_.cells();
    g_.resize(Q * view_.pstride);
    type_.upload(lattice_.types());
    tag_.upload(lattice_.tags());
    walls_.upload(lattice_.wall_motions());
    bnd_cell_.upload(lattice_.boundary_cells());
    bnd_normal_.upload(lattice_.boundary_normals());
    bnd_value_.upload(lattice_.boundary_values());
    bnd_mask_.upload(lattice_.boundary_link_masks());
    bnd_grad_cell_.upload(lattice_.boundary_gradient_cells());
    bnd_grad_weight_.upload(lattice_.boundary_gradient_weights());
    held_cell_.upload(lattice_.held_cells());
    held_wall_.upload(lattice_.held_walls());
    absorbing_cell_.upload(lattice_.absorbing_cells());
    absorbing_target_.upload(lattice_.absorbing_targets());
    absorbing_sigma_.upload(lattice_.absorbing_sigmas());
    row_offsets_.upload(lattice_.row_offsets());
    link_mask_.upload(full_link_masks(lattice_));
    if (!lattice_.boundary_cells().empty()) aux_.resize(4 * n);
    check(cudaMalloc(&flag_, sizeof(unsigned long long)), "cudaMalloc");
    sync_view();
    do_initialize({}, {});
  }
  ~CudaSolver() override {
    cudaFree(flag_);
    cudaFree(fastest_);
    if (fastest_host_) cudaFreeHost(fastest_host_);
    if (fed_) cudaEventDestroy(fed_);
    if (staged_) cudaEventDestroy(staged_);
    if (pinned_) cudaFreeHost(pinned_);
  }
  const char* backend_name() const override { return "cuda"; }
  void synchronize() override { check(cudaDeviceSynchronize(), "step"); }

  void set_force_field(const std::vector<float>& f) override {
    const std::size_t n = lattice_.cells();
    if (f.empty()) {
      force_.resize(0);
    } else {
      if (f.size() != 3 * n) throw ConfigError("set_force_field: expected 3 values per cell");
      std::vector<float> soa(3 * n);
      for (std::size_t c = 0; c < n; ++c)
        for (int a = 0; a < 3; ++a) {
          if (!std::isfinite(f[3 * c + a])) throw ConfigError("set_force_field: force is not finite");
          soa[a * n + c] = f[3 * c + a];
        }
      force_.upload(soa);
    }
    sync_view();
  }

  void do_set_boundary_values(const std::vector<float>& values) override { bnd_value_.upload(values); }

  bool feeds_from_grid() const override { return true; }
  void do_feed_from_grid(const GridWindowView& w0, std::uint64_t serial0, const GridWindowView& w1, std::uint64_t serial1,
                         const GridFeed& feed) override {
    GridWindowView d[2] = {w0, w1};
    const std::uint64_t serial[2] = {serial0, serial1};
    for (int s = 0; s < 2; ++s) {
      const std::size_t n = 3 * static_cast<std::size_t>(d[s].n[0]) * d[s].n[1] * d[s].n[2];
      if (serial[s] == 0 || serial[s] != window_serial_[s]) {  // a new window: one upload per table frame
        if (window_[s].size() != n) window_[s].resize(n);
        if (n) check(cudaMemcpy(window_[s].data(), d[s].u, n * sizeof(float), cudaMemcpyHostToDevice), "window upload");
        window_serial_[s] = serial[s];
      }
      d[s].u = window_[s].data();
    }
    if (!fastest_) {
      check(cudaMalloc(&fastest_, sizeof(unsigned)), "cudaMalloc");
      check(cudaMallocHost(&fastest_host_, sizeof(unsigned)), "cudaMallocHost");
      check(cudaEventCreateWithFlags(&fed_, cudaEventDisableTiming), "event");
    }
    // queued behind the step, not waited for: the speed is read at the next feed (do_fed_speed)
    check(cudaMemsetAsync(fastest_, 0, sizeof(unsigned), 0), "memset");
    if (view_.nbnd) grid_feed_kernel<<<blocks(view_.nbnd), kBlock>>>(view_, bnd_value_.data(), feed, d[0], d[1], fastest_);
    check(cudaGetLastError(), "feed launch");
    check(cudaMemcpyAsync(fastest_host_, fastest_, sizeof(unsigned), cudaMemcpyDeviceToHost, 0), "download");
    check(cudaEventRecord(fed_, 0), "event");
  }
  float do_fed_speed() override {
    if (!fed_) return 0.0f;
    check(cudaEventSynchronize(fed_), "feed");
    float f;
    std::memcpy(&f, fastest_host_, sizeof f);
    return f;
  }
  void do_pull_boundary_values() override { bnd_value_.download(boundary_values_); }
  // the device copy may be newer than the host's (a device feed): clear it in place, no upload
  void do_clear_reference_change() override {
    if (view_.nbnd) clear_reference_change_kernel<<<blocks(view_.nbnd), kBlock>>>(view_, bnd_value_.data());
    check(cudaGetLastError(), "clear launch");
  }

  // Only the listed cells cross the bus (the default would download or upload whole fields).
  void do_velocities(bool next_odd, const std::vector<std::uint32_t>& cells, std::vector<float>& out) override {
    if (cells.empty()) return;
    if (cells != gather_host_) {
      gather_cells_.upload(cells);
      gather_host_ = cells;
    }
    if (gather_out_.size() != out.size()) gather_out_.resize(out.size());
    if (next_odd)
      gather_velocity_kernel<true><<<blocks(cells.size()), kBlock>>>(view_, gather_cells_.data(), cells.size(), gather_out_.data());
    else
      gather_velocity_kernel<false><<<blocks(cells.size()), kBlock>>>(view_, gather_cells_.data(), cells.size(), gather_out_.data());
    check(cudaGetLastError(), "velocities");
    float* staging = pinned(out.size());  // page-locked: one direct copy, no staging by the driver
    check(cudaMemcpyAsync(staging, gather_out_.data(), out.size() * sizeof(float), cudaMemcpyDeviceToHost, 0), "download");
    check(cudaStreamSynchronize(0), "download");
    std::copy(staging, staging + out.size(), out.begin());
  }

  // The force field, zero where nothing was set, once listed cells get forces.
  void ensure_force_field() {
    const std::size_t n = lattice_.cells();
    if (force_.size() == 3 * n) return;
    force_.resize(3 * n);
    check(cudaMemset(force_.data(), 0, 3 * n * sizeof(float)), "force field");
    sync_view();
  }

  void do_set_cell_forces(const std::vector<std::uint32_t>& cells, const std::vector<float>& f) override {
    const std::size_t n = lattice_.cells();
    ensure_force_field();
    if (cells.empty()) return;
    if (cells != scatter_host_) {
      scatter_cells_.upload(cells);
      scatter_host_ = cells;
    }
    if (scatter_values_.size() != f.size()) scatter_values_.resize(f.size());
    float* staging = pinned(f.size());  // the copy is queued before the step's kernels, not waited for
    std::copy(f.begin(), f.end(), staging);
    check(cudaMemcpyAsync(scatter_values_.data(), staging, f.size() * sizeof(float), cudaMemcpyHostToDevice, 0), "upload");
    check(cudaEventRecord(staged_, 0), "event");
    scatter_force_kernel<<<blocks(cells.size()), kBlock>>>(force_.data(), n, scatter_cells_.data(), cells.size(), scatter_values_.data());
    check(cudaGetLastError(), "cell forces");
  }

  // The columns stay on the device; each new set of coefficients is one launch (force_columns_: the
  // column count, set by the base after this call).
  void do_set_cell_force_columns(const std::vector<std::uint32_t>& cells, const std::vector<float>& basis, int) override {
    device_column_cells_.upload(cells);
    device_column_basis_.upload(basis);
  }
  void do_set_cell_force_coefficients(const std::vector<float>& coefficients) override {
    ensure_force_field();
    const std::size_t n = device_column_cells_.size();
    if (n == 0) return;
    ColumnCoefficients k{};
    std::copy(coefficients.begin(), coefficients.end(), k.c);
    column_force_kernel<<<blocks(n), kBlock>>>(force_.data(), lattice_.cells(), device_column_cells_.data(), n, device_column_basis_.data(),
                                               force_columns_, k);
    check(cudaGetLastError(), "cell forces");
  }

  void do_set_populations(const std::vector<float>& g) override {
    std::vector<pop_t> h;
    g_.download(h);  // keeps the padding between the population planes
    const std::size_t n = lattice_.cells();
    for (int i = 0; i < Q; ++i)
      for (std::size_t c = 0; c < n; ++c) h[i * view_.pstride + c] = store_pop(g[i * n + c]);
    g_.upload(h);
  }
  std::vector<float> do_cell_state() override {
    std::vector<float> h;
    if (aux_.size()) aux_.download(h);
    return h;
  }
  void do_set_cell_state(const std::vector<float>& a) override { aux_.upload(a); }
  std::vector<float> populations() override {
    std::vector<pop_t> h;
    g_.download(h);
    const std::size_t n = lattice_.cells();
    std::vector<float> out(Q * n);
    for (int i = 0; i < Q; ++i)
      for (std::size_t c = 0; c < n; ++c) out[i * n + c] = load_pop(h[i * view_.pstride + c]);
    return out;
  }

 protected:
  void sync_walls() override { walls_.upload(lattice_.wall_motions()); }
  void sync_view() override {
    view_.g = g_.data();
    view_.type = type_.data();
    view_.tag = tag_.data();
    view_.walls = walls_.data();
    view_.force = force_.size() ? force_.data() : nullptr;
    view_.bnd_cell = bnd_cell_.data();
    view_.bnd_normal = bnd_normal_.data();
    view_.bnd_mask = bnd_mask_.data();
    view_.bnd_value = bnd_value_.data();
    view_.aux = aux_.size() ? aux_.data() : nullptr;
    view_.row_offsets = row_offsets_.data();
    view_.bnd_grad_cell = bnd_grad_cell_.data();
    view_.bnd_grad_weight = bnd_grad_weight_.data();
    view_.held_cell = held_cell_.data();
    view_.held_wall = held_wall_.data();
    view_.absorbing_cell = absorbing_cell_.data();
    view_.absorbing_target = absorbing_target_.data();
    view_.absorbing_sigma = absorbing_sigma_.data();
  }

  void do_initialize(const std::vector<float>& rho, const std::vector<float>& u) override {
    DeviceArray<float> drho, du;
    drho.upload(rho);
    du.upload(u);
    init_kernel<<<blocks(view_.ncells), kBlock>>>(view_, rho.empty() ? nullptr : drho.data(), u.empty() ? nullptr : du.data());
    if (view_.nbnd) init_boundary_kernel<<<blocks(view_.nbnd), kBlock>>>(view_);
    check(cudaDeviceSynchronize(), "initialize");
  }

  // The passes of a step (see update_boundary_state in lattice_view.hpp), in stream order.
  template <bool kOdd, int kCollision, int kForce>
  void launch_step() {
    fluid_kernel<kOdd, kCollision, kForce><<<blocks(view_.ncells), kBlock>>>(view_, link_mask_.data());
    if (view_.nbnd) {
      boundary_state_kernel<kOdd><<<blocks(view_.nbnd), kBlock>>>(view_);
      boundary_kernel<kOdd, kCollision, kForce><<<blocks(view_.nbnd), kBlock>>>(view_);
    }
  }
  template <bool kOdd, int kCollision>
  void launch_step_forced() {
    switch (force_mode(view_)) {
      case kNoForce:
        return launch_step<kOdd, kCollision, kNoForce>();
      case kUniformForce:
        return launch_step<kOdd, kCollision, kUniformForce>();
      case kForceField:
        return launch_step<kOdd, kCollision, kForceField>();
      case kFrameForce:
        return launch_step<kOdd, kCollision, kFrameForce>();
      default:
        return launch_step<kOdd, kCollision, kFrameForceField>();
    }
  }
  template <bool kOdd>
  void run_step() {
    with_collision_kind(view_.params, [&](auto kind) { launch_step_forced<kOdd, decltype(kind)::value>(); });
  }
  void do_step(bool odd) override {
    odd ? run_step<true>() : run_step<false>();
    check(cudaGetLastError(), "step launch");
    if (view_.nheld) {  // the held cells after the step (hold_cell, parity of the step done)
      const unsigned nb = blocks(static_cast<std::size_t>(view_.nheld));
      if (odd)
        hold_kernel<true><<<nb, kBlock>>>(view_);
      else
        hold_kernel<false><<<nb, kBlock>>>(view_);
      check(cudaGetLastError(), "hold launch");
    }
    if (view_.nabsorbing) {  // the absorbing layers' cells (absorb_cell; disjoint from the held cells)
      const unsigned nb = blocks(static_cast<std::size_t>(view_.nabsorbing));
      if (odd)
        absorb_kernel<true><<<nb, kBlock>>>(view_);
      else
        absorb_kernel<false><<<nb, kBlock>>>(view_);
      check(cudaGetLastError(), "absorb launch");
    }
  }

  void do_fields(bool next_odd, Fields& out) override {
    DeviceArray<float> rho(view_.ncells), u(3 * view_.ncells);
    if (next_odd)
      fields_kernel<true><<<blocks(view_.ncells), kBlock>>>(view_, rho.data(), u.data());
    else
      fields_kernel<false><<<blocks(view_.ncells), kBlock>>>(view_, rho.data(), u.data());
    check(cudaGetLastError(), "fields");
    rho.download(out.rho);
    u.download(out.u);
  }

  long long do_find_divergent(bool next_odd, float limit) override {
    const unsigned long long none = ~0ULL;
    check(cudaMemcpy(flag_, &none, sizeof(none), cudaMemcpyHostToDevice), "guard");
    if (next_odd)
      divergence_kernel<true><<<blocks(view_.ncells), kBlock>>>(view_, limit * limit, flag_);
    else
      divergence_kernel<false><<<blocks(view_.ncells), kBlock>>>(view_, limit * limit, flag_);
    unsigned long long first = none;
    check(cudaMemcpy(&first, flag_, sizeof(first), cudaMemcpyDeviceToHost), "guard");
    return first == none ? -1 : static_cast<long long>(first);
  }

 private:
  // Page-locked staging buffer for the listed-cell exchange. Before it is rewritten, the copy queued
  // from it last (staged_) must be done.
  float* pinned(std::size_t n) {
    if (!staged_) check(cudaEventCreateWithFlags(&staged_, cudaEventDisableTiming), "event");
    check(cudaEventSynchronize(staged_), "staging");
    if (n > pinned_size_) {
      if (pinned_) cudaFreeHost(pinned_);
      pinned_ = nullptr;
      check(cudaMallocHost(&pinned_, n * sizeof(float)), "cudaMallocHost");
      pinned_size_ = n;
    }
    return pinned_;
  }
  DeviceArray<pop_t> g_;
  DeviceArray<std::uint8_t> type_, tag_, bnd_normal_, held_wall_;
  DeviceArray<WallMotion> walls_;
  DeviceArray<std::uint32_t> bnd_cell_, bnd_mask_, bnd_grad_cell_, held_cell_;
  DeviceArray<float> bnd_value_, force_, aux_, bnd_grad_weight_;
  DeviceArray<std::int64_t> row_offsets_;
  DeviceArray<std::uint32_t> absorbing_cell_, absorbing_target_;  // Lattice::absorbing_cells, absorbing_targets
  DeviceArray<float> absorbing_sigma_;
  DeviceArray<std::uint32_t> link_mask_;  // per cell (read by cells off the bulk path only)
  // listed-cell exchange (velocities, cell forces): the cell lists stay on the device while unchanged
  DeviceArray<std::uint32_t> gather_cells_, scatter_cells_;
  std::vector<std::uint32_t> gather_host_, scatter_host_;
  DeviceArray<float> gather_out_, scatter_values_;
  // the force columns on the device (set_cell_force_columns): cells and columns
  DeviceArray<std::uint32_t> device_column_cells_;
  DeviceArray<float> device_column_basis_;
  unsigned long long* flag_ = nullptr;
  // the gridded field the faces are fed from (feed_from_grid): two frames of a window, and the serial
  // numbers of the windows they were copied from
  DeviceArray<float> window_[2];
  std::uint64_t window_serial_[2] = {0, 0};
  unsigned* fastest_ = nullptr;       // largest face speed of the last feed (float bits)
  unsigned* fastest_host_ = nullptr;  // its page-locked copy, valid once fed_ has passed
  cudaEvent_t fed_ = nullptr;
  cudaEvent_t staged_ = nullptr;
  float* pinned_ = nullptr;
  std::size_t pinned_size_ = 0;
};

}  // namespace

bool cuda_available() {
  int count = 0;
  if (cudaGetDeviceCount(&count) != cudaSuccess) {
    cudaGetLastError();
    return false;
  }
  return count > 0;
}

std::unique_ptr<Solver> make_cuda_solver(Lattice lattice) { return std::make_unique<CudaSolver>(std::move(lattice)); }

namespace {
// Best of 10 timed launches over arrays of at least 1 GiB (beyond the H100's 50 MiB L2); GB/s
// counting 2 * bytes per pass.
template <typename Launch>
double device_bandwidth(std::size_t bytes, Launch launch) {
  if (!cuda_available()) throw ConfigError("device bandwidth: no CUDA device");
  const std::size_t n = std::max<std::size_t>(bytes, std::size_t(1) << 30) / sizeof(float4);
  DeviceArray<float4> a(n), b(n);
  check(cudaMemset(a.data(), 0, n * sizeof(float4)), "memset");
  cudaEvent_t t0, t1;
  cudaEventCreate(&t0);
  cudaEventCreate(&t1);
  float best = 1e30f;
  for (int rep = 0; rep < 10; ++rep) {
    cudaEventRecord(t0);
    launch(a.data(), b.data(), n);
    cudaEventRecord(t1);
    cudaEventSynchronize(t1);
    float ms = 0;
    cudaEventElapsedTime(&ms, t0, t1);
    if (rep > 0) best = std::min(best, ms);
  }
  check(cudaGetLastError(), "bandwidth kernel");
  cudaEventDestroy(t0);
  cudaEventDestroy(t1);
  return 2.0 * n * sizeof(float4) / (best * 1e-3) * 1e-9;
}
}  // namespace

double device_copy_bandwidth_gbs(std::size_t bytes) {
  return device_bandwidth(bytes, [](float4* a, float4* b, std::size_t n) { copy_kernel<<<132 * 16, 256>>>(a, b, n); });
}

double device_inplace_bandwidth_gbs(std::size_t bytes) {
  return device_bandwidth(bytes, [](float4* a, float4*, std::size_t n) { inplace_kernel<<<132 * 16, 256>>>(a, n); });
}

}  // namespace ship_lrm::lbm
