#include "ship_lrm/lbm/solver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "ship_lrm/lbm/cell_ops.hpp"
#include "ship_lrm/lbm/column_series.hpp"
#include "ship_lrm/lbm/refill.hpp"

namespace ship_lrm::lbm {

Backend parse_backend(const std::string& s) {
  if (s == "cpu") return Backend::Cpu;
  if (s == "cuda") return Backend::Cuda;
  if (s == "auto") return Backend::Auto;
  throw ConfigError("unknown backend '" + s + "' (use cpu, cuda or auto)");
}

const char* to_string(Backend b) { return b == Backend::Cpu ? "cpu" : (b == Backend::Cuda ? "cuda" : "auto"); }

CollisionModel parse_collision_model(const std::string& s) {
  if (s == "bgk") return CollisionModel::Bgk;
  if (s == "recursive") return CollisionModel::RecursiveRegularized;
  throw ConfigError("unknown collision '" + s + "' (use bgk or recursive)");
}

const char* to_string(CollisionModel m) { return m == CollisionModel::Bgk ? "bgk" : "recursive"; }

static std::string divergence_message(long step, int x, int y, int z, float density, float speed, float limit) {
  std::ostringstream s;
  s << "LBM diverged at step " << step << ", cell (" << x << ", " << y << ", " << z << "): density " << density << ", speed " << speed
    << " (lattice units; the guard wants a density > 0 and a finite speed up to " << limit
    << "); lower the lattice velocity, raise the resolution or the Smagorinsky constant";
  return s.str();
}

DivergenceError::DivergenceError(long step_, int x_, int y_, int z_, float density, float speed, float limit)
    : std::runtime_error(divergence_message(step_, x_, y_, z_, density, speed, limit)), step(step_), x(x_), y(y_), z(z_) {}

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
    view_.face_inflow_reference[f] = cfg.faces[f].inflow_from_reference ? 1 : 0;
    view_.face_pressure_relaxation[f] = cfg.faces[f].pressure_relaxation;
    view_.face_total_pressure[f] = cfg.faces[f].total_pressure_inflow ? 1 : 0;
    view_.face_characteristic[f] = cfg.faces[f].characteristic_inlet ? 1 : 0;
  }
  view_.params = cfg.collision;
  view_.nbnd = static_cast<int>(lattice_.boundary_cells().size());
  view_.nheld = static_cast<int>(lattice_.held_cells().size());
  view_.nabsorbing = static_cast<int>(lattice_.absorbing_cells().size());
  boundary_values_ = lattice_.boundary_values();
}

void Solver::clear_reference_change() {
  const auto& cells = lattice_.boundary_cells();
  for (std::size_t b = 0; b < cells.size(); ++b)
    if (static_cast<CellType>(lattice_.types()[cells[b]] & ~kGeneralBit) == CellType::ImpedanceOutlet) boundary_values_[4 * b + 3] = 0.0f;
  do_clear_reference_change();
  reference_change_pending_ = false;
}

void Solver::do_clear_reference_change() { do_set_boundary_values(boundary_values_); }

void Solver::check_fed_speed() {
  if (!feed_unchecked_) return;
  feed_unchecked_ = false;
  const float fastest = do_fed_speed();
  if (!(fastest <= max_setup_speed()))
    throw ConfigError("a face fed from the grid reached " + std::to_string(fastest) + " lattice units, beyond the Mach limit " +
                      std::to_string(max_setup_speed()) + " (kMaxSetupMach c_s): lower the lattice velocity or raise N");
}

void Solver::pull_boundary_values() {
  check_fed_speed();
  if (!boundary_values_on_device_) return;
  do_pull_boundary_values();
  boundary_values_on_device_ = false;
}

const std::vector<float>& Solver::boundary_values() {
  pull_boundary_values();
  return boundary_values_;
}

void Solver::feed_from_grid(const GridWindowView& w0, std::uint64_t serial0, const GridWindowView& w1, std::uint64_t serial1,
                            const GridFeed& feed) {
  if (!feeds_from_grid()) throw ConfigError(std::string("feed_from_grid: the ") + backend_name() + " backend does not feed faces itself");
  check_fed_speed();  // the previous feed's
  do_feed_from_grid(w0, serial0, w1, serial1, feed);
  boundary_values_on_device_ = feed_unchecked_ = true;
  reference_change_pending_ = true;  // the impedance outlets follow the change in the next step
}

void Solver::feed_faces_from_grid(const GridWindowView& w0, std::uint64_t serial0, const GridWindowView& w1, std::uint64_t serial1,
                                  const GridFeed& feed) {
  if (feeds_from_grid()) {
    feed_from_grid(w0, serial0, w1, serial1, feed);
    return;
  }
  pull_boundary_values();
  const auto& cells = lattice_.boundary_cells();
  const auto& normals = lattice_.boundary_normals();
  const auto& types = lattice_.types();
  const int nx = lattice_.nx(), ny = lattice_.ny();
  std::vector<float> next = boundary_values_;
  float fastest = 0.0f;
  bool impedance_fed = false;
  const long n = static_cast<long>(cells.size());
#pragma omp parallel for reduction(max : fastest) reduction(|| : impedance_fed)
  for (long b = 0; b < n; ++b) {
    const auto t = static_cast<CellType>(types[cells[b]] & ~kGeneralBit);
    if (t != CellType::VelocityInlet && t != CellType::ImpedanceOutlet) continue;
    const std::uint32_t c = cells[b];
    const int x = static_cast<int>(c % nx), y = static_cast<int>((c / nx) % ny),
              z = static_cast<int>(c / (static_cast<std::uint32_t>(nx) * ny));
    float* value = &next[4 * b];
    feed_boundary_cell(feed, w0, w1, t == CellType::ImpedanceOutlet, normals[b], x, y, z, value);
    const float speed = std::sqrt(value[0] * value[0] + value[1] * value[1] + value[2] * value[2]);
    fastest = std::isfinite(speed) ? std::max(fastest, speed) : std::numeric_limits<float>::infinity();
    impedance_fed = impedance_fed || t == CellType::ImpedanceOutlet;
  }
  if (std::isinf(fastest)) {  // a NaN or an infinity in a fed value: the lattice (its outlets' own state) or the field has diverged
    for (long b = 0; b < n; ++b) {
      const float* v = &next[4 * b];
      if (std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]) && std::isfinite(v[3])) continue;
      const std::uint32_t c = cells[b];
      throw DivergenceError(steps_, static_cast<int>(c % nx), static_cast<int>((c / nx) % ny),
                            static_cast<int>(c / (static_cast<std::uint32_t>(nx) * ny)), v[3], std::numeric_limits<float>::infinity(),
                            max_setup_speed());
    }
  }
  if (!(fastest <= max_setup_speed()))
    throw ConfigError("feed_faces_from_grid: a fed face would reach lattice speed " + std::to_string(fastest) + ", beyond the Mach limit " +
                      std::to_string(kMaxSetupMach) + " c_s");
  boundary_values_ = std::move(next);
  reference_change_pending_ = reference_change_pending_ || impedance_fed;
  do_set_boundary_values(boundary_values_);
}

void Solver::set_boundary_values(const std::vector<float>& values) {
  if (values.size() != boundary_values_.size()) throw ConfigError("set_boundary_values: expected 4 values per open-boundary cell");
  for (float v : values)
    if (!std::isfinite(v)) throw ConfigError("set_boundary_values: value is not finite");
  const auto& cells = lattice_.boundary_cells();
  const auto& normals = lattice_.boundary_normals();
  pull_boundary_values();
  for (std::size_t b = 0; b < cells.size(); ++b) {
    const auto t = static_cast<CellType>(lattice_.types()[cells[b]] & ~kGeneralBit);
    float shift = 0.0f;
    if (t == CellType::ImpedanceOutlet) {
      // outward normal change of the reference, added to any change not yet stepped
      shift = impedance_reference_shift(boundary_values_[4 * b + 3], normals[b], &boundary_values_[4 * b], &values[4 * b]);
      reference_change_pending_ = reference_change_pending_ || shift != 0.0f;
    }
    for (int k = 0; k < 3; ++k) boundary_values_[4 * b + k] = values[4 * b + k];
    boundary_values_[4 * b + 3] = t == CellType::ImpedanceOutlet ? shift : values[4 * b + 3];
  }
  do_set_boundary_values(boundary_values_);
}

float max_setup_speed() { return kMaxSetupMach * std::sqrt(d3q19::cs2); }

long first_invalid_setup_cell(const std::vector<float>& rho, const std::vector<float>& u, float* speed) {
  const float umax = max_setup_speed();
  const std::size_t n = std::max(rho.size(), u.size() / 3);
  for (std::size_t c = 0; c < n; ++c) {
    const float s = c < u.size() / 3 ? std::sqrt(u[3 * c] * u[3 * c] + u[3 * c + 1] * u[3 * c + 1] + u[3 * c + 2] * u[3 * c + 2]) : 0.0f;
    const bool bad_rho = c < rho.size() && !(rho[c] > 0.0f && rho[c] < 2.0f);
    if (bad_rho || !(s <= umax)) {
      if (speed) *speed = s;
      return static_cast<long>(c);
    }
  }
  return -1;
}

void Solver::initialize(const std::vector<float>& rho, const std::vector<float>& u) {
  const std::size_t n = lattice_.cells();
  if (!rho.empty() && rho.size() != n) throw ConfigError("initialize: density field has the wrong size");
  if (!u.empty() && u.size() != 3 * n) throw ConfigError("initialize: velocity field has the wrong size (3 per cell)");
  const long bad = first_invalid_setup_cell(rho, u);
  if (bad >= 0 && !rho.empty() && !(rho[bad] > 0.0f && rho[bad] < 2.0f))
    throw ConfigError("initialize: density must lie in (0, 2) lattice units");
  if (bad >= 0) throw ConfigError("initialize: initial velocity above the Mach limit or not finite");
  start_from(rho, u);
}

void Solver::start_from(const std::vector<float>& rho, const std::vector<float>& u) {
  if (reference_change_pending_) {  // the new state is the reference's: nothing left to follow
    clear_reference_change();
  }
  do_initialize(rho, u);
  steps_ = 0;
}

void Solver::restore(long steps, const std::vector<float>& g) {
  if (steps < 0) throw ConfigError("restore: negative step count");
  if (g.size() != static_cast<std::size_t>(d3q19::Q) * lattice_.cells())
    throw ConfigError("restore: expected " + std::to_string(d3q19::Q) + " populations per cell for this lattice, got " +
                      std::to_string(g.size()));
  for (float v : g)
    if (!std::isfinite(v)) throw ConfigError("restore: the populations are not finite");
  if (reference_change_pending_) clear_reference_change();
  do_set_populations(g);
  steps_ = steps;
}

Solver::OpenBoundaryState Solver::open_boundary_state() {
  OpenBoundaryState s;
  s.cell_state = do_cell_state();
  s.values = boundary_values();
  return s;
}

void Solver::restore_open_boundary_state(const OpenBoundaryState& s) {
  const std::size_t cells = lattice_.boundary_cells().empty() ? 0 : 4 * lattice_.cells();
  if (s.cell_state.size() != cells || s.values.size() != boundary_values_.size())
    throw ConfigError("restore_open_boundary_state: the state is not this lattice's (" + std::to_string(s.cell_state.size()) +
                      " cell values, expected " + std::to_string(cells) + "; " + std::to_string(s.values.size()) +
                      " boundary values, expected " + std::to_string(boundary_values_.size()) + ")");
  for (const auto* v : {&s.cell_state, &s.values})
    for (float x : *v)
      if (!std::isfinite(x)) throw ConfigError("restore_open_boundary_state: a value is not finite");
  pull_boundary_values();
  boundary_values_ = s.values;
  do_set_boundary_values(boundary_values_);
  if (cells) do_set_cell_state(s.cell_state);
}

void Solver::step(long n) {
  const int interval = lattice_.config().guard_interval;
  for (long k = 0; k < n; ++k) {
    do_step(steps_ % 2 == 1);
    ++steps_;
    if (reference_change_pending_) clear_reference_change();  // the impedance outlets took it in this step
    if (interval > 0 && steps_ % interval == 0) check_divergence();
  }
}

namespace {
bool same_face(const FaceCondition& a, const FaceCondition& b) {
  return a.type == b.type && a.velocity == b.velocity && a.density == b.density && a.inflow_from_reference == b.inflow_from_reference &&
         a.pressure_relaxation == b.pressure_relaxation && a.total_pressure_inflow == b.total_pressure_inflow &&
         a.characteristic_inlet == b.characteristic_inlet && a.absorbing_cells == b.absorbing_cells &&
         a.absorbing_strength == b.absorbing_strength;
}
bool same_setup(const LatticeConfig& a, const LatticeConfig& b) {
  bool same = a.nx == b.nx && a.ny == b.ny && a.nz == b.nz && a.collision.nu == b.collision.nu &&
              a.collision.smagorinsky == b.collision.smagorinsky && a.uniform_force == b.uniform_force && a.mach_guard == b.mach_guard &&
              a.guard_interval == b.guard_interval;
  for (int f = 0; f < 6 && same; ++f) same = same_face(a.faces[f], b.faces[f]);
  return same;
}
}  // namespace

bool Solver::change_walls(Lattice& next, bool restart_flow) {
  if (!in_place_walls() || !same_setup(lattice_.config(), next.config()) || next.wall_motions().size() != lattice_.wall_motions().size())
    return false;
  next.finalize();
  const Lattice& was = lattice_;
  // the open boundaries' state (aux, boundary values) is kept per boundary cell: the same cells
  if (next.boundary_cells() != was.boundary_cells() || next.boundary_normals() != was.boundary_normals()) return false;
  std::vector<std::uint32_t> freed;  // cells that leave a wall
  const auto wall = [](const Lattice& l, std::size_t c) { return is_wall(static_cast<CellType>(l.types()[c] & ~kGeneralBit)); };
  for (std::size_t c = 0; c < was.cells(); ++c)
    if (wall(was, c) && !wall(next, c)) freed.push_back(static_cast<std::uint32_t>(c));
  if (restart_flow) {  // the whole flow at equilibrium with its density and velocity, as a new solver would start
    // (from restart_fields: the cells that stay walls keep fields()'s rest state, no step reads them)
    const Fields f = restart_fields(was, fields(), freed);
    float speed = 0;
    const long bad = first_invalid_setup_cell(f.rho, f.u, &speed);
    if (bad >= 0) {  // the flow itself is beyond the set-up limits: it has diverged (nothing changed)
      const long nx = was.nx(), ny = was.ny();
      throw DivergenceError(steps_, static_cast<int>(bad % nx), static_cast<int>((bad / nx) % ny), static_cast<int>(bad / (nx * ny)),
                            f.rho[bad], speed, max_setup_speed());
    }
    do_change_walls(std::move(next), {}, {});
    view_.nheld = static_cast<int>(lattice_.held_cells().size());
    view_.nabsorbing = static_cast<int>(lattice_.absorbing_cells().size());
    start_from(f.rho, f.u);  // checked above
    return true;
  }
  const bool odd = steps_ % 2 == 1;
  const auto states = refill_states(was, freed, [&](std::size_t c) {
    const Macro m = do_cell_state(odd, c);
    return std::array<float, 4>{m.rho, m.u[0], m.u[1], m.u[2]};
  });
  do_change_walls(std::move(next), freed, states);
  view_.nheld = static_cast<int>(lattice_.held_cells().size());
  view_.nabsorbing = static_cast<int>(lattice_.absorbing_cells().size());
  return true;
}

Macro Solver::do_cell_state(bool, std::size_t) { throw ConfigError(std::string(backend_name()) + ": no in-place wall change"); }
void Solver::do_change_walls(Lattice&&, const std::vector<std::uint32_t>&, const std::vector<std::array<float, 4>>&) {
  throw ConfigError(std::string(backend_name()) + ": no in-place wall change");
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

void Solver::set_cell_forces(const std::vector<std::uint32_t>& cells, const std::vector<float>& f) {
  if (f.size() != 3 * cells.size()) throw ConfigError("set_cell_forces: expected 3 values per listed cell");
  for (std::size_t k = 0; k < cells.size(); ++k) {
    if (cells[k] >= lattice_.cells()) throw ConfigError("set_cell_forces: cell index out of range");
    for (int a = 0; a < 3; ++a)
      if (!std::isfinite(f[3 * k + a])) throw ConfigError("set_cell_forces: force is not finite");
  }
  do_set_cell_forces(cells, f);
}

void Solver::set_cell_force_columns(const std::vector<std::uint32_t>& cells, const std::vector<float>& basis, int columns) {
  if (columns < 1 || columns > kMaxForceColumns)
    throw ConfigError("set_cell_force_columns: " + std::to_string(columns) + " columns, expected 1 to " + std::to_string(kMaxForceColumns));
  if (basis.size() != static_cast<std::size_t>(columns) * cells.size())
    throw ConfigError("set_cell_force_columns: expected " + std::to_string(columns) + " values per listed cell");
  for (std::uint32_t c : cells)
    if (c >= lattice_.cells()) throw ConfigError("set_cell_force_columns: cell index out of range");
  for (float b : basis)
    if (!std::isfinite(b)) throw ConfigError("set_cell_force_columns: a column value is not finite");
  do_set_cell_force_columns(cells, basis, columns);
  force_columns_ = columns;
}

void Solver::set_cell_force_coefficients(const std::vector<float>& coefficients) {
  if (force_columns_ == 0) throw ConfigError("set_cell_force_coefficients: call set_cell_force_columns first");
  if (coefficients.size() != 3 * static_cast<std::size_t>(force_columns_))
    throw ConfigError("set_cell_force_coefficients: expected 3 values per column (" + std::to_string(force_columns_) + " columns)");
  for (float c : coefficients)
    if (!std::isfinite(c)) throw ConfigError("set_cell_force_coefficients: a coefficient is not finite");
  do_set_cell_force_coefficients(coefficients);
}

void Solver::do_set_cell_force_columns(const std::vector<std::uint32_t>& cells, const std::vector<float>& basis, int) {
  column_cells_ = cells;
  column_basis_ = basis;
}

void Solver::do_set_cell_force_coefficients(const std::vector<float>& coefficients) {
  const std::size_t n = column_cells_.size();
  column_sums_.resize(3 * n);
  column_series(column_basis_.data(), n, 0, n, force_columns_, coefficients.data(), column_sums_.data(), n);
  column_forces_.resize(3 * n);
  for (std::size_t k = 0; k < n; ++k)
    for (int a = 0; a < 3; ++a) column_forces_[3 * k + a] = column_sums_[a * n + k];
  do_set_cell_forces(column_cells_, column_forces_);
}

void Solver::set_uniform_force(const std::array<float, 3>& f) {
  for (int a = 0; a < 3; ++a) {
    if (!std::isfinite(f[a])) throw ConfigError("set_uniform_force: force is not finite");
    view_.uniform_force[a] = f[a];
  }
  sync_view();
}

FrameForce frame_force(const FrameMotion& m) {
  const auto& w = m.omega;
  const auto& dw = m.omega_dot;
  const float ww = w[0] * w[0] + w[1] * w[1] + w[2] * w[2];
  // a(p) = -a_O - dw x r - w x (w x r), r = p - centre; w x (w x r) = w (w.r) - |w|^2 r.
  // gradient G = -[dw]x - (w w^T - |w|^2 I); accel = -a_O - G centre.
  FrameForce f;
  float* G = f.gradient;
  const float cross[9] = {0, -dw[2], dw[1], dw[2], 0, -dw[0], -dw[1], dw[0], 0};
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) G[3 * a + b] = -cross[3 * a + b] - w[a] * w[b] + (a == b ? ww : 0.0f);
  for (int a = 0; a < 3; ++a) {
    f.accel[a] = -m.acceleration[a];
    for (int b = 0; b < 3; ++b) f.accel[a] -= G[3 * a + b] * m.centre[b];
    f.omega[a] = w[a];
  }
  return f;
}

void Solver::set_frame_motion(const FrameMotion& m) {
  bool any = false;
  for (int a = 0; a < 3; ++a) {
    for (float x : {m.acceleration[a], m.omega[a], m.omega_dot[a], m.centre[a]})
      if (!std::isfinite(x)) throw ConfigError("set_frame_motion: a value is not finite");
    any = any || m.acceleration[a] != 0.0f || m.omega[a] != 0.0f || m.omega_dot[a] != 0.0f;
  }
  view_.frame = frame_force(m);
  view_.frame_active = any;
  sync_view();
}

void Solver::set_wall_motion(int wall, const WallMotion& m) {
  lattice_.set_wall_motion(wall, m);
  sync_walls();
}

void Solver::check_divergence() {
  const float limit = lattice_.config().mach_guard * std::sqrt(d3q19::cs2);
  const long long c = do_find_divergent(steps_ % 2 == 1, limit);
  if (c < 0) return;
  // only on failure: the moments the guard tested, from the cell's own populations (an open-boundary
  // cell's fields() would report the state its condition imposed last step instead); between steps a
  // cell's populations sit in its own slots, in opposite order after an odd step, which flips j only
  const std::vector<float> g = populations();
  const std::size_t n = lattice_.cells();
  float gc[d3q19::Q], rho, j[3];
  for (int i = 0; i < d3q19::Q; ++i) gc[i] = g[static_cast<std::size_t>(i) * n + static_cast<std::size_t>(c)];
  moments(gc, rho, j);
  const int nx = lattice_.nx(), ny = lattice_.ny();
  throw DivergenceError(steps_, static_cast<int>(c % nx), static_cast<int>((c / nx) % ny),
                        static_cast<int>(c / (static_cast<long long>(nx) * ny)), rho,
                        std::sqrt(j[0] * j[0] + j[1] * j[1] + j[2] * j[2]) / rho, limit);
}

std::unique_ptr<Solver> make_solver(Lattice lattice, Backend backend) {
  if (backend == Backend::Cpu) return make_cpu_solver(std::move(lattice));
  if (backend == Backend::Cuda) return make_cuda_solver(std::move(lattice));
  return cuda_available() ? make_cuda_solver(std::move(lattice)) : make_cpu_solver(std::move(lattice));
}

}  // namespace ship_lrm::lbm
