#include "ship_lrm/lbm/solver.hpp"

#include <cmath>
#include <sstream>

namespace ship_lrm::lbm {

Backend parse_backend(const std::string& s) {
  if (s == "cpu") return Backend::Cpu;
  if (s == "cuda") return Backend::Cuda;
  if (s == "auto") return Backend::Auto;
  throw ConfigError("unknown backend '" + s + "' (use cpu, cuda or auto)");
}

const char* to_string(Backend b) { return b == Backend::Cpu ? "cpu" : (b == Backend::Cuda ? "cuda" : "auto"); }

static std::string divergence_message(long step, int x, int y, int z, float speed, float limit) {
  std::ostringstream s;
  s << "LBM diverged at step " << step << ", cell (" << x << ", " << y << ", " << z << "): speed " << speed
    << " (lattice units) is not finite or above the guard limit " << limit
    << "; lower the lattice velocity, raise the resolution or the Smagorinsky constant";
  return s.str();
}

DivergenceError::DivergenceError(long step_, int x_, int y_, int z_, float speed, float limit)
    : std::runtime_error(divergence_message(step_, x_, y_, z_, speed, limit)), step(step_), x(x_), y(y_), z(z_) {}

Solver::Solver(Lattice lattice) : lattice_(std::move(lattice)) {
  lattice_.finalize();
  const LatticeConfig& cfg = lattice_.config();
  view_.n[0] = cfg.nx;
  view_.n[1] = cfg.ny;
  view_.n[2] = cfg.nz;
  view_.ncells = lattice_.cells();
  view_.pstride = population_stride(view_.ncells);
  for (int a = 0; a < 3; ++a) view_.uniform_force[a] = cfg.uniform_force[a];
  for (int f = 0; f < 6; ++f) {
    view_.face[f] = static_cast<std::uint8_t>(cfg.faces[f].type);
    for (int a = 0; a < 3; ++a) view_.face_velocity[f][a] = cfg.faces[f].velocity[a];
  }
  view_.params = cfg.collision;
  view_.nbnd = static_cast<int>(lattice_.boundary_cells().size());
}

void Solver::initialize(const std::vector<float>& rho, const std::vector<float>& u) {
  const std::size_t n = lattice_.cells();
  if (!rho.empty() && rho.size() != n) throw ConfigError("initialize: density field has the wrong size");
  if (!u.empty() && u.size() != 3 * n) throw ConfigError("initialize: velocity field has the wrong size (3 per cell)");
  for (float r : rho)
    if (!(r > 0.0f && r < 2.0f)) throw ConfigError("initialize: density must lie in (0, 2) lattice units");
  const float umax = kMaxSetupMach * std::sqrt(d3q19::cs2);
  for (std::size_t c = 0; c < u.size() / 3; ++c) {
    const float s = std::sqrt(u[3 * c] * u[3 * c] + u[3 * c + 1] * u[3 * c + 1] + u[3 * c + 2] * u[3 * c + 2]);
    if (!(s <= umax)) throw ConfigError("initialize: initial velocity above the Mach limit or not finite");
  }
  do_initialize(rho, u);
  steps_ = 0;
}

void Solver::step(long n) {
  const int interval = lattice_.config().guard_interval;
  for (long k = 0; k < n; ++k) {
    do_step(steps_ % 2 == 1);
    ++steps_;
    if (interval > 0 && steps_ % interval == 0) check_divergence();
  }
}

Fields Solver::fields() {
  Fields f;
  f.rho.resize(lattice_.cells());
  f.u.resize(3 * lattice_.cells());
  do_fields(steps_ % 2 == 1, f);
  return f;
}

std::vector<float> Solver::velocities(const std::vector<std::uint32_t>& cells) {
  for (std::uint32_t c : cells)
    if (c >= lattice_.cells()) throw ConfigError("velocities: cell index out of range");
  std::vector<float> out(3 * cells.size());
  do_velocities(steps_ % 2 == 1, cells, out);
  return out;
}

void Solver::do_velocities(bool, const std::vector<std::uint32_t>& cells, std::vector<float>& out) {
  const Fields f = fields();
  for (std::size_t k = 0; k < cells.size(); ++k)
    for (int a = 0; a < 3; ++a) out[3 * k + a] = f.u[3 * static_cast<std::size_t>(cells[k]) + a];
}

void Solver::set_cell_forces(const std::vector<std::uint32_t>& cells, const std::vector<float>& f) {
  if (f.size() != 3 * cells.size()) throw ConfigError("set_cell_forces: expected 3 values per listed cell");
  for (std::size_t k = 0; k < cells.size(); ++k) {
    if (cells[k] >= lattice_.cells()) throw ConfigError("set_cell_forces: cell index out of range");
    for (int a = 0; a < 3; ++a)
      if (!std::isfinite(f[3 * k + a])) throw ConfigError("set_cell_forces: force is not finite");
  }
  do_set_cell_forces(cells, f);
}

void Solver::do_set_cell_forces(const std::vector<std::uint32_t>& cells, const std::vector<float>& f) {
  if (force_mirror_.empty()) force_mirror_.assign(3 * lattice_.cells(), 0.0f);
  for (std::size_t k = 0; k < cells.size(); ++k)
    for (int a = 0; a < 3; ++a) force_mirror_[3 * static_cast<std::size_t>(cells[k]) + a] = f[3 * k + a];
  set_force_field(force_mirror_);
}

void Solver::set_uniform_force(const std::array<float, 3>& f) {
  for (int a = 0; a < 3; ++a) {
    if (!std::isfinite(f[a])) throw ConfigError("set_uniform_force: force is not finite");
    view_.uniform_force[a] = f[a];
  }
  sync_view();
}

void Solver::check_divergence() {
  const float limit = lattice_.config().mach_guard * std::sqrt(d3q19::cs2);
  const long long c = do_find_divergent(steps_ % 2 == 1, limit);
  if (c < 0) return;
  const Fields f = fields();  // only on failure: the full (streamed) state of the cell for the message
  const int nx = lattice_.nx(), ny = lattice_.ny();
  const float* u = &f.u[3 * c];
  throw DivergenceError(steps_, static_cast<int>(c % nx), static_cast<int>((c / nx) % ny),
                        static_cast<int>(c / (static_cast<long long>(nx) * ny)), std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]), limit);
}

std::unique_ptr<Solver> make_solver(Lattice lattice, Backend backend) {
  if (backend == Backend::Cpu) return make_cpu_solver(std::move(lattice));
  if (backend == Backend::Cuda) return make_cuda_solver(std::move(lattice));
  return cuda_available() ? make_cuda_solver(std::move(lattice)) : make_cpu_solver(std::move(lattice));
}

}  // namespace ship_lrm::lbm
