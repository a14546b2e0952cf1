// The LRM fluid domain (see domain.hpp).
#include "ship_lrm/lrm/domain.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

#include "ship_lrm/lbm/refill.hpp"
#include "ship_lrm/rotor/vortex_cylinder.hpp"

namespace ship_lrm::lrm {
namespace {

lbm::UnitReference unit_reference(const LrmConfig& c) {
  if (!(c.reach >= 1.0)) throw ConfigError("LRM: the reach factor a must be >= 1 (domain edge a * 4R), got " + std::to_string(c.reach));
  for (double s : c.outlet_sigma)
    if (!(s >= 0.0 && s <= 10.0)) throw ConfigError("LRM: the outlet sigma must lie in [0, 10], got " + std::to_string(s));
  if (c.nodes < 16) throw ConfigError("LRM: N must be >= 16 nodes per 4R, got " + std::to_string(c.nodes));
  if (!(c.radius > 0)) throw ConfigError("LRM: the rotor radius must be > 0");
  lbm::UnitReference r;
  r.length = 4.0 * c.radius;
  r.nodes = c.nodes;
  r.velocity = c.reference_velocity;
  r.viscosity = c.viscosity;
  r.density = c.density;
  return r;
}

int edge_cells(const LrmConfig& c) { return static_cast<int>(std::lround(c.reach * (c.nodes - 1))) + 1; }

lbm::Lattice make_lattice(const LrmConfig& c, const lbm::UnitConverter& u, int edge) {
  lbm::LatticeConfig lc;
  lc.nx = lc.ny = lc.nz = edge;
  lc.collision.nu = static_cast<float>(u.lattice_viscosity());
  lc.collision.smagorinsky = static_cast<float>(c.smagorinsky);
  lc.collision.model = c.collision;
  for (int f = 0; f < 6; ++f) {
    lc.faces[f].type = c.faces[f];
    lc.faces[f].inflow_from_reference = true;  // the faces know the undisturbed air (set_motion)
    // Poinsot & Lele's (1992) K = sigma (1 - M^2) c / L in lattice units (c_s per step, L = the edge in cells); the stream's
    // Mach number is that of the reference velocity at most
    const double mach = u.mach_number();
    lc.faces[f].total_pressure_inflow = c.entraining_pressure_faces && c.faces[f] == lbm::FaceType::PressureOutlet;
    lc.faces[f].characteristic_inlet = c.characteristic_inlets && c.faces[f] == lbm::FaceType::VelocityInlet;
    if (c.faces[f] == lbm::FaceType::VelocityInlet && c.absorbing_layer > 0) {
      lc.faces[f].absorbing_cells = c.absorbing_layer;
      lc.faces[f].absorbing_strength = static_cast<float>(c.absorbing_strength);
    }
    if (c.faces[f] == lbm::FaceType::ImpedanceOutlet)
      lc.faces[f].pressure_relaxation = static_cast<float>(c.outlet_sigma[f] * (1.0 - mach * mach) / std::sqrt(3.0) / (edge - 1));
  }
  lc.mach_guard = 0.9f;
  return lbm::Lattice(lc);
}

}  // namespace

LrmConfig config_for_stream(LrmConfig cfg, double fastest_stream) {
  cfg.reference_velocity = std::max(cfg.reference_velocity, std::abs(fastest_stream));
  return cfg;
}

lbm::UnitConverter lattice_units(const LrmConfig& cfg) { return lbm::UnitConverter(unit_reference(cfg)); }

LrmDomain::LrmDomain(const LrmConfig& cfg)
    : cfg_(cfg),
      units_(unit_reference(cfg)),
      edge_(edge_cells(cfg)),
      centre_(0.5 * (edge_ - 1)),
      disk_(edge_, edge_, centre_, centre_, cfg.radius / units_.dx()),
      disk_layer_(static_cast<int>(std::lround(centre_))) {
  for (const auto& c : disk_.cells())
    disk_cells_.push_back(
        static_cast<std::uint32_t>(c.i + static_cast<std::size_t>(edge_) * (c.j + static_cast<std::size_t>(edge_) * disk_layer_)));
  faces_hold_air_ = std::any_of(cfg.faces.begin(), cfg.faces.end(),
                                [](lbm::FaceType f) { return f == lbm::FaceType::VelocityInlet || f == lbm::FaceType::ImpedanceOutlet; });
  owner_.assign(static_cast<std::size_t>(edge_) * edge_ * edge_, -1);
  inside_ = owner_;
  rebuild(false);
}

lbm::WallMotion LrmDomain::lattice_motion(const WallSurface& wall) const {
  const RigidMotion& m = wall.motion();
  lbm::WallMotion w;
  // The bodies kept clear of the faces drain, through their clipped faces, what the faces feed into
  // the held air in front of them: Ladd's rho_w must be the fluid's density there (design.md, "Ladd's
  // wall density"). The others keep the reference density.
  w.local_density = wall.clear_of_faces() ? 1.0f : 0.0f;
  for (int d = 0; d < 3; ++d) {
    w.v[d] = static_cast<float>(m.velocity[d] * units_.dt() / units_.dx());
    w.omega[d] = static_cast<float>(m.omega[d] * units_.dt());
    w.centre[d] = static_cast<float>(centre_);
  }
  return w;
}

void LrmDomain::add_wall(std::shared_ptr<WallSurface> wall) {
  if (!wall) throw ConfigError("LRM: add_wall got no wall");
  if (walls_.size() >= 255) throw ConfigError("LRM: at most 255 walls");
  walls_.push_back(std::move(wall));
  try {
    update_walls();
  } catch (...) {
    walls_.pop_back();  // the domain stays as it was
    throw;
  }
}

void LrmDomain::update_walls() {
  const auto start = std::chrono::steady_clock::now();
  struct Timer {  // wall_seconds_, also when the change throws
    const std::chrono::steady_clock::time_point& start;
    double& total;
    ~Timer() { total += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); }
  } timer{start, wall_seconds_};
  // voxelise: cell centres inside a body
  std::vector<std::int16_t> owner(owner_.size(), -1), inside(owner_.size(), -1);
  std::vector<bool> moves(walls_.size());
  for (size_t w = 0; w < walls_.size(); ++w) {
    moves[w] = builds_as_moving_wall(*walls_[w]);
  }
  std::vector<bool> clear(walls_.size());
  for (size_t w = 0; w < walls_.size(); ++w) clear[w] = walls_[w]->clear_of_faces();
  const int lo = kClearLayers, hi = edge_ - 1 - kClearLayers;  // the two outermost layers on every side
  // Blocks of kB^3 cells: a wall whose distance at the block's centre exceeds the distance to the
  // block's farthest cell centre misses (or, below minus that, fills) the whole block, since a signed
  // distance changes by at most the distance moved (WallSurface). Only blocks a surface passes
  // through are voxelised cell by cell; the result is the same as cell by cell everywhere.
  constexpr int kB = 4;
  const double reach = std::sqrt(3.0) * 0.5 * (kB - 1) * units_.dx() * (1.0 + 1e-9) + 1e-12;
  std::size_t count = 0;
  std::vector<signed char> state(walls_.size());  // per block: +1 misses, -1 fills, 0 cell by cell
  for (int k0 = 0; k0 < edge_; k0 += kB)
    for (int j0 = 0; j0 < edge_; j0 += kB)
      for (int i0 = 0; i0 < edge_; i0 += kB) {
        const int i1 = std::min(i0 + kB, edge_), j1 = std::min(j0 + kB, edge_), k1 = std::min(k0 + kB, edge_);
        const Vec3 centre = 0.5 * (position(i0, j0, k0) + position(i1 - 1, j1 - 1, k1 - 1));
        bool any = false;
        for (size_t w = 0; w < walls_.size(); ++w) {
          const double d = walls_[w]->signed_distance(centre);
          state[w] = d > reach ? 1 : (d < -reach ? -1 : 0);
          any = any || state[w] != 1;
        }
        if (!any) continue;
        for (int k = k0; k < k1; ++k)
          for (int j = j0; j < j1; ++j)
            for (int i = i0; i < i1; ++i) {
              const bool outer = i < lo || j < lo || k < lo || i > hi || j > hi || k > hi;
              const std::size_t c = i + static_cast<std::size_t>(edge_) * (j + static_cast<std::size_t>(edge_) * k);
              for (size_t w = 0; w < walls_.size(); ++w) {
                if (state[w] == 1 || (state[w] == 0 && walls_[w]->signed_distance(position(i, j, k)) >= 0.0)) continue;
                if (outer && clear[w]) {  // inside, where no wall may stand: the air moves with the body
                  if (inside[c] < 0) inside[c] = static_cast<std::int16_t>(w);
                  continue;
                }
                owner[c] = static_cast<std::int16_t>(w);
                inside[c] = -1;
                ++count;
                break;
              }
            }
      }
  for (size_t k = 0; k < disk_cells_.size(); ++k)
    if (owner[disk_cells_[k]] >= 0) throw WallOnRotorDisk(walls_[owner[disk_cells_[k]]]->name());
  const bool same = owner == owner_ && inside == inside_ && moves == wall_moves_;
  bool near_faces = false;  // a wall cell changed in the layers next to those kept clear
  for (std::size_t c = 0; c < owner.size() && !same && !near_faces; ++c)
    near_faces = owner[c] != owner_[c] && face_layer(c) <= kClearLayers + 1;
  owner_ = std::move(owner);
  inside_ = std::move(inside);
  wall_moves_ = std::move(moves);
  wall_cells_ = count;
  if (!same) {
    rebuild(true, near_faces);
    ++rebuilds_;
    if (near_faces) ++face_restarts_;
  }
  push_wall_motions();  // the motions themselves change without a rebuild
}

void LrmDomain::push_wall_motions() {
  for (size_t w = 0, slot = 0; w < walls_.size(); ++w)
    if (wall_moves_[w]) solver_->set_wall_motion(static_cast<int>(slot++), lattice_motion(*walls_[w]));
  if (!body_faces_.empty() && motion_set_) push_face_values();  // the bodies' velocities at their face cells
}

bool LrmDomain::find_body_faces() {
  std::vector<std::pair<std::uint32_t, std::int16_t>> found;
  const lbm::Lattice& lat = solver_->lattice();
  const auto& cells = lat.boundary_cells();
  for (std::size_t k = 0; k < cells.size(); ++k)
    if (inside_[cells[k]] >= 0 && (lat.types()[cells[k]] & ~lbm::kGeneralBit) != static_cast<std::uint8_t>(lbm::CellType::PressureOutlet))
      found.emplace_back(static_cast<std::uint32_t>(k), inside_[cells[k]]);
  const bool changed = found != body_faces_;
  body_faces_ = std::move(found);
  return changed;
}

void LrmDomain::push_face_values() {
  if (body_faces_.empty()) return solver_->set_boundary_values(face_values_);
  std::vector<float> values = face_values_;
  const auto& cells = solver_->lattice().boundary_cells();
  std::vector<lbm::WallMotion> motions(walls_.size());  // per body, not per cell (every step low over the sea)
  for (size_t w = 0; w < walls_.size(); ++w)
    if (wall_moves_[w]) motions[w] = lattice_motion(*walls_[w]);
  const auto e = static_cast<std::uint32_t>(edge_);  // (boundary cells are 32-bit indices)
  for (const auto& [k, w] : body_faces_) {
    const std::uint32_t c = cells[k];
    const float x = static_cast<float>(c % e), y = static_cast<float>((c / e) % e), z = static_cast<float>(c / (e * e));
    lbm::rigid_velocity(motions[w], x, y, z, &values[4 * k]);
  }
  solver_->set_boundary_values(values);
}

void LrmDomain::update_wall_motions() {
  for (size_t w = 0; w < walls_.size(); ++w)
    if (wall_moves_[w] != builds_as_moving_wall(*walls_[w])) return update_walls();
  push_wall_motions();
}

bool LrmDomain::builds_as_moving_wall(const WallSurface& wall) const {
  const RigidMotion m = wall.motion();
  if (!wall.slip()) return m.moving();
  // Specular reflection imposes no tangential velocity, so a slip body may slide along itself (the
  // ground passing under a rotor in forward flight), never move across itself.
  if (wall.clear_of_faces())
    throw ConfigError("LRM: the slip wall '" + wall.name() +
                      "' cannot be kept clear of the faces (the air held inside it does not slide with a slip wall)");
  if (!m.omega.isZero(0))
    throw ConfigError("LRM: the slip wall '" + wall.name() + "' turns relative to the domain; a slip wall may only slide along itself");
  // the surface's normal from the signed distance's gradient at the hub (exact for a plane)
  const double h = units_.dx();
  Vec3 normal;
  for (int a = 0; a < 3; ++a) normal[a] = (wall.signed_distance(h * Vec3::Unit(a)) - wall.signed_distance(-h * Vec3::Unit(a))) / (2 * h);
  const double across = normal.norm() > 0 ? m.velocity.dot(normal.normalized()) : m.velocity.norm();
  if (!(std::abs(across) <= 1e-9 * (1.0 + m.velocity.norm())))
    throw ConfigError("LRM: the slip wall '" + wall.name() + "' moves across itself at " + std::to_string(across) +
                      " m/s; a slip wall may only slide along itself");
  return false;
}

int LrmDomain::face_layer(std::size_t c) const {
  const int i = static_cast<int>(c % edge_), j = static_cast<int>((c / edge_) % edge_);
  const int k = static_cast<int>(c / (static_cast<std::size_t>(edge_) * edge_));
  return std::min({i, j, k, edge_ - 1 - i, edge_ - 1 - j, edge_ - 1 - k});
}

void LrmDomain::rebuild(bool carry_flow, bool near_faces) {
  lbm::Lattice lat = make_lattice(cfg_, units_, edge_);
  std::vector<int> slot(walls_.size(), -1);
  for (size_t w = 0; w < walls_.size(); ++w)
    if (wall_moves_.size() > w && wall_moves_[w]) slot[w] = lat.add_wall_motion(lattice_motion(*walls_[w]));
  for (int k = 0; k < edge_; ++k)
    for (int j = 0; j < edge_; ++j)
      for (int i = 0; i < edge_; ++i) {
        const std::size_t c = lat.index(i, j, k);
        // inside a body kept clear of the faces: fluid held to the body's motion (face cells: their
        // values, push_face_values)
        if (inside_[c] >= 0 && lat.type(i, j, k) == lbm::CellType::Fluid)
          lat.set_held(i, j, k, slot[inside_[c]] >= 0 ? slot[inside_[c]] : lbm::Lattice::kHeldAtRest);
        const int w = owner_[c];
        if (w < 0) continue;
        if (slot[w] >= 0)
          lat.set_moving_wall(i, j, k, slot[w]);
        else if (walls_[w]->slip())
          lat.set_slip_wall(i, j, k);
        else
          lat.set_wall(i, j, k);
      }
  // In place where the backend can (the CPU): the forces, faces and frame motion stay with the
  // solver, and the flow keeps its history unless wall cells changed next to the layers kept clear
  // of walls; there it restarts at equilibrium, as a new solver does (kept history drifted there even
  // with the held cells; design.md, "Walls that move"). Otherwise (CUDA, or walls through a face) a
  // new solver.
  if (carry_flow && solver_ && solver_->change_walls(lat, near_faces)) {
    if (find_body_faces() && motion_set_) {
      motion_set_ = false;  // the faces inside a body changed: push the faces again
      set_motion(motion_);
    }
    return;
  }
  lbm::Fields carried;
  if (carry_flow && solver_) carried = lbm::carry_flow(solver_->lattice(), solver_->fields());
  const std::vector<float>& rho = carried.rho;
  const std::vector<float>& u = carried.u;
  const std::vector<std::uint32_t> old_boundary = solver_ ? solver_->lattice().boundary_cells() : std::vector<std::uint32_t>{};
  solver_ = lbm::make_solver(std::move(lat), cfg_.backend);
  if (solver_->lattice().boundary_cells() != old_boundary) face_air_stale_ = far_field_stale_ = true;  // walls moved through a face
  face_positions_.clear();  // a new solver: its boundary cells (set_motion lists them again)
  find_body_faces();
  if (disk_force_columns_.empty()) disk_force_columns_ = disk_.force_columns();
  solver_->set_cell_force_columns(disk_cells_, disk_force_columns_, rotor::DiskCoupling::kForceColumns);
  if (!disk_force_coefficients_.empty()) solver_->set_cell_force_coefficients(disk_force_coefficients_);
  if (motion_set_) {
    motion_set_ = false;  // push the faces and the frame forces to the new solver
    set_motion(motion_);
  }
  // after the faces: the carried state is the reference the impedance outlets start from
  if (!rho.empty()) {
    try {
      solver_->initialize(rho, u);
    } catch (const ConfigError&) {
      // the carried flow itself is beyond the set-up limits: the LRM flow has diverged, the input is fine
      float speed = 0;
      const long c = lbm::first_invalid_setup_cell(rho, u, &speed);
      if (c < 0) throw;
      const long e = edge_;
      throw lbm::DivergenceError(steps_, static_cast<int>(c % e), static_cast<int>((c / e) % e), static_cast<int>(c / (e * e)), rho[c],
                                 speed, lbm::max_setup_speed());
    }
  } else
    solver_->initialize({}, {});
}

Vec3 LrmDomain::undisturbed_air(const Vec3& r) const {
  Vec3 air = motion_.air_velocity;
  if (grid_) lbm::grid_air(grid_->feed, grid_->window[0], grid_->window[1], r.data(), air.data());
  return air - motion_.omega.cross(r);
}

Vec3 LrmDomain::position(int i, int j, int k) const { return Vec3(i - centre_, j - centre_, k - centre_) * units_.dx(); }

Vec3 LrmDomain::position(std::size_t cell) const {
  return position(static_cast<int>(cell % edge_), static_cast<int>((cell / edge_) % edge_),
                  static_cast<int>(cell / (static_cast<std::size_t>(edge_) * edge_)));
}

void LrmDomain::set_stream(const Vec3& air) {
  Motion m;
  m.air_velocity = air;
  set_motion(m);
}

void LrmDomain::set_motion(const Motion& m) {
  for (const Vec3* v : {&m.air_velocity, &m.omega, &m.omega_dot, &m.hub_acceleration})
    if (!v->allFinite()) throw ConfigError("LRM: the domain motion is not finite");
  if (!faces_hold_air_ && (m.air_velocity.norm() > 0 || m.omega.norm() > 0))
    throw ConfigError("LRM: all six faces are pressure faces, which hold only air at rest; a stream (here " +
                      std::to_string(m.air_velocity.norm()) +
                      " m/s) or a turning domain needs a velocity face (e.g. the front: --faces ambient-sides) or impedance faces");
  // with a face grid the faces do not use air_velocity (set_face_grid)
  const bool far_field_changed = update_far_field(m.air_velocity);
  const bool faces_same =
      motion_set_ && !far_field_changed && (grid_ || m.air_velocity == motion_.air_velocity) && m.omega == motion_.omega;
  const bool frame_same =
      motion_set_ && m.omega == motion_.omega && m.omega_dot == motion_.omega_dot && m.hub_acceleration == motion_.hub_acceleration;
  if (faces_same && frame_same) return;  // unchanged (the coupled step calls this every step)
  const double to_lattice = units_.dt() / units_.dx();
  const double cs = 1.0 / std::sqrt(3.0);
  if (!faces_same && grid_ && solver_->feeds_from_grid() && !cfg_.rotor_far_field && body_faces_.empty()) {
    // the field is interpolated where the faces live (one kernel); the Mach limit is checked there
    lbm::GridFeed f = grid_->feed;
    for (int d = 0; d < 3; ++d) f.omega[d] = m.omega[d];
    f.to_lattice = to_lattice;
    f.dx = units_.dx();
    f.centre = centre_;
    solver_->feed_from_grid(grid_->window[0], grid_->serial[0], grid_->window[1], grid_->serial[1], f);
  } else if (!faces_same) {
    const auto& cells = solver_->lattice().boundary_cells();
    const long ncells = static_cast<long>(cells.size());
    if (face_positions_.size() != cells.size()) {  // once per solver: in a manoeuvre this runs every step
      face_positions_.resize(cells.size());
      for (long k = 0; k < ncells; ++k) face_positions_[k] = position(cells[k]);
    }
    const auto cell_position = [&](long k) { return face_positions_[k]; };
    if (grid_ && face_air_stale_) {  // the grid's air at each face cell (grid_feed.hpp, as the CUDA kernel)
      face_air_.resize(cells.size());
#pragma omp parallel for schedule(static)
      for (long k = 0; k < ncells; ++k) {
        const Vec3 r = cell_position(k);
        lbm::grid_air(grid_->feed, grid_->window[0], grid_->window[1], r.data(), face_air_[k].data());
      }
      face_air_stale_ = false;
    }
    std::vector<float>& values = face_values_;
    values.assign(4 * cells.size(), 0.0f);
    double fastest = 0;
    // every step in a manoeuvre (omega changes) and at each wake-table refresh: on the OpenMP threads
#pragma omp parallel for schedule(static) reduction(max : fastest)
    for (long k = 0; k < ncells; ++k) {
      const Vec3 r = cell_position(k);
      Vec3 air = grid_ ? face_air_[k] : m.air_velocity;
      if (!far_field_.empty()) air += far_field_[k];
      Vec3 u;
      lbm::face_lattice_velocity(air.data(), m.omega.data(), r.data(), to_lattice, u.data());
      fastest = std::max(fastest, u.norm());
      const size_t c = cells[k];
      if ((solver_->lattice().types()[c] & ~lbm::kGeneralBit) == static_cast<std::uint8_t>(lbm::CellType::PressureOutlet)) {
        values[4 * k] = 1.0f;  // the undisturbed air's density (a pressure outlet holds its density)
        continue;
      }
      for (int d = 0; d < 3; ++d) values[4 * k + d] = static_cast<float>(u[d]);
    }
    if (fastest > lbm::kMaxSetupMach * cs)
      throw ConfigError("LRM: a face velocity of " + std::to_string(fastest / to_lattice) + " m/s is beyond the lattice Mach limit " +
                        std::to_string(lbm::kMaxSetupMach) + " at N = " + std::to_string(cfg_.nodes) +
                        " (largest: " + std::to_string(units_.to_physical_velocity(lbm::kMaxSetupMach * cs)) + " m/s)");
    push_face_values();
  }
  if (!frame_same) {
    lbm::FrameMotion f;
    const double dt = units_.dt();
    for (int d = 0; d < 3; ++d) {
      f.acceleration[d] = static_cast<float>(m.hub_acceleration[d] * dt * dt / units_.dx());
      f.omega[d] = static_cast<float>(m.omega[d] * dt);
      f.omega_dot[d] = static_cast<float>(m.omega_dot[d] * dt * dt);
      f.centre[d] = static_cast<float>(centre_);
    }
    solver_->set_frame_motion(f);
  }
  motion_ = m;
  motion_set_ = true;
}

void LrmDomain::set_face_grid(const lbm::GridWindowView (&window)[2], const std::uint64_t (&serial)[2], const lbm::GridFeed& grid,
                              const Vec3& hub, const Mat3& rotation, const Vec3& hub_velocity) {
  if (!hub.allFinite() || !rotation.allFinite() || !hub_velocity.allFinite()) throw ConfigError("LRM: the face grid's pose is not finite");
  FaceGrid next;
  next.feed = grid;
  for (int d = 0; d < 3; ++d) {
    next.feed.hub[d] = hub[d];
    next.feed.hub_velocity[d] = hub_velocity[d];
    for (int e = 0; e < 3; ++e) next.feed.rotation[3 * d + e] = rotation(d, e);
  }
  for (int s = 0; s < 2; ++s) {
    next.window[s] = window[s];
    next.serial[s] = serial[s];
    for (int old = 0; old < 2 && !next.data[s]; ++old)  // a window fed before is shared, not copied
      if (grid_ && serial[s] != 0 && grid_->serial[old] == serial[s]) next.data[s] = grid_->data[old];
    if (!next.data[s]) {
      const std::size_t n = 3 * static_cast<std::size_t>(window[s].n[0]) * window[s].n[1] * window[s].n[2];
      next.data[s] = std::make_shared<const std::vector<float>>(window[s].u, window[s].u + n);
    }
    next.window[s].u = next.data[s]->data();
  }
  std::optional<FaceGrid> previous = std::move(grid_);
  std::vector<Vec3> previous_air = std::move(face_air_);
  const bool was_set = motion_set_, was_stale = face_air_stale_;
  const Vec3 previous_hub_air = hub_air_;
  const bool previous_hub_air_set = hub_air_set_;
  const double previous_hub_air_time = hub_air_time_;
  grid_ = std::move(next);
  if (cfg_.rotor_far_field) {
    // the grid's air at the disk's centre, relative to the hub, low-passed over 1 s (the rotor's far
    // field is that of its mean wake; the LRM resolves the gusts)
    const Vec3 r(0, 0, (disk_layer_ - centre_) * units_.dx());
    Vec3 air;
    lbm::grid_air(grid_->feed, grid_->window[0], grid_->window[1], r.data(), air.data());
    const double weight = hub_air_set_ ? 1.0 - std::exp(-std::max(0.0, time() - hub_air_time_) / 1.0) : 1.0;
    hub_air_ += weight * (air - hub_air_);
    hub_air_time_ = time();
    hub_air_set_ = true;
  }
  face_air_stale_ = true;
  motion_set_ = false;  // push the faces again
  try {
    set_motion(motion_);
  } catch (...) {
    grid_ = std::move(previous);
    face_air_ = std::move(previous_air);
    hub_air_ = previous_hub_air;
    hub_air_set_ = previous_hub_air_set;
    hub_air_time_ = previous_hub_air_time;
    face_air_stale_ = was_stale;
    motion_set_ = was_set;
    throw;
  }
}

void LrmDomain::clear_face_grid() {
  if (!grid_) return;
  grid_.reset();
  face_air_.clear();
  hub_air_set_ = false;  // a later grid starts its hub air afresh
  face_air_stale_ = true;
  motion_set_ = false;
  set_motion(motion_);
}

void LrmDomain::restart_flow() {
  const size_t n = solver_->lattice().cells();
  const double to_lattice = units_.dt() / units_.dx();
  std::vector<float> u(3 * n);
  for (int l = 0; l < edge_; ++l)
    for (int j = 0; j < edge_; ++j)
      for (int i = 0; i < edge_; ++i) {
        const Vec3 v = undisturbed_air(position(i, j, l)) * to_lattice;
        const size_t k = solver_->lattice().index(i, j, l);
        for (int d = 0; d < 3; ++d) u[3 * k + d] = static_cast<float>(v[d]);
      }
  solver_->initialize(std::vector<float>(n, 1.0f), u);
}

bool LrmDomain::update_far_field(const Vec3& motion_air) {
  if (!cfg_.rotor_far_field) return false;
  // with a face grid (a ship's wake) the air the rotor sits in: the grid's at the disk's centre,
  // averaged over the last second (set_face_grid); else the undisturbed air of set_motion
  const Vec3 air = grid_ && hub_air_set_ ? hub_air_ : motion_air;
  const double thrust = rotor_thrust_;
  const double speed = std::max(air.norm(), far_field_air_.norm());
  const bool thrust_moved = std::abs(thrust - far_field_thrust_) > 0.02 * std::max(std::abs(thrust), std::abs(far_field_thrust_));
  const bool air_moved = (air - far_field_air_).norm() > 0.02 * speed;
  if (!far_field_stale_ && !thrust_moved && !air_moved) return false;
  const auto& cells = solver_->lattice().boundary_cells();
  if (thrust > 0) {
    // the disk's cell layer lies disk_layer_ - centre_ cells below the hub
    const Vec3 disk_centre(0, 0, (disk_layer_ - centre_) * units_.dx());
    std::optional<rotor::VortexCylinderWake> built;  // its constructor is cheap (momentum theory); velocity() is not
    try {
      built.emplace(cfg_.radius, thrust, cfg_.density, air, units_.dx());
      if (far_field_ground_ < std::numeric_limits<double>::infinity()) built->set_ground(far_field_ground_ - disk_centre.z());
    } catch (const std::invalid_argument& e) {
      throw ConfigError(std::string("LRM: the rotor's far field at the faces: ") + e.what());
    }
    const rotor::VortexCylinderWake& wake = *built;
    // Its shape depends on the wake's direction only (and the ground), its size on v: rebuilt when the
    // direction turns by more than 1 deg (a sheet 3 R away moves by 0.26 m, 0.4 cells at N = 32, within
    // the rings' core of a cell), else rescaled; so a thrust that varies from step to step costs a
    // multiplication per cell.
    const double kTurn = std::cos(1.0 * M_PI / 180.0);
    if (far_field_stale_ || far_field_shape_.size() != cells.size() || wake.wake_direction().dot(far_field_direction_) < kTurn) {
      const auto start = std::chrono::steady_clock::now();
      far_field_shape_.assign(cells.size(), Vec3::Zero());
      const double per_v = 1.0 / wake.mean_induced();
      const long n = static_cast<long>(cells.size());
#pragma omp parallel for schedule(dynamic, 64)
      for (long k = 0; k < n; ++k) far_field_shape_[k] = per_v * wake.velocity(position(cells[k]) - disk_centre);
      far_field_direction_ = wake.wake_direction();
      ++far_field_builds_;
      far_field_seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
    ++far_field_updates_;
    far_field_.resize(cells.size());
    for (size_t k = 0; k < cells.size(); ++k) far_field_[k] = wake.mean_induced() * far_field_shape_[k];
  } else {
    far_field_.assign(cells.size(), Vec3::Zero());
  }
  far_field_thrust_ = thrust;
  far_field_air_ = air;
  far_field_stale_ = false;
  return true;
}

void LrmDomain::set_far_field_ground(double height) {
  const double disk = (disk_layer_ - centre_) * units_.dx();  // the disk's cell layer below the hub
  if (!(height > disk))                                       // NaN too; infinity (no ground) passes
    throw ConfigError("LRM: the rotor far field's ground plane must lie below the disk (" + std::to_string(disk) +
                      " m below the hub), not " + std::to_string(height) + " m");
  far_field_ground_ = height;
  far_field_stale_ = true;
}

void LrmDomain::set_rotor_forces(const rotor::RotorForceHarmonics& h) {
  rotor_thrust_ = -h.cos[0].z();  // the mean aerodynamic force on the blades, thrust along -z
  if (motion_set_ && update_far_field(motion_.air_velocity)) {
    motion_set_ = false;  // push the faces with the new far field
    const Motion m = motion_;
    try {
      set_motion(m);
    } catch (...) {
      motion_set_ = true;
      throw;
    }
  }
  // N per cell on the blades -> the lattice force density on the air (the opposite force over the
  // cell's volume; to_lattice_force_density is linear), summed where the lattice lives
  const double volume = std::pow(units_.dx(), 3);
  std::vector<float> coefficients;
  disk_.force_coefficients(h, units_.to_lattice_force_density(-1.0 / volume), coefficients);
  solver_->set_cell_force_coefficients(coefficients);
  disk_force_coefficients_ = std::move(coefficients);
}

void LrmDomain::step(long n) {
  solver_->step(n);
  steps_ += n;
}

rotor::RotorInflow LrmDomain::inflow() {
  const std::vector<float> u = solver_->velocities(disk_cells_);
  const double scale = units_.dx() / units_.dt();
  return disk_.extract([&](size_t k) { return Vec3(u[3 * k] * scale, u[3 * k + 1] * scale, u[3 * k + 2] * scale); });
}

}  // namespace ship_lrm::lrm
