// The ship-wake domain (see wake_domain.hpp).
#include "ship_lrm/wake/wake_domain.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "ship_lrm/lbm/refill.hpp"
#include "ship_lrm/wake/ship_voxels.hpp"

namespace ship_lrm::wake {
lbm::UnitConverter wake_units(const WakeConfig& cfg, double ship_length) {
  if (cfg.cells_per_length < 16)
    throw ConfigError("wake: N must be >= 16 cells per ship length, got " + std::to_string(cfg.cells_per_length));
  if (!(cfg.wind > 0) || !std::isfinite(cfg.wind)) throw ConfigError("wake: the wind must be > 0 m/s");
  if (!(ship_length > 0)) throw ConfigError("wake: the ship has no length");
  lbm::UnitReference r;
  r.length = ship_length;
  r.nodes = cfg.cells_per_length + 1;  // dx = l / N
  r.velocity = cfg.wind;
  r.lattice_velocity = cfg.lattice_wind;
  r.viscosity = cfg.viscosity;
  r.density = cfg.density;
  return lbm::UnitConverter(r);  // ConfigError beyond the Mach limit
}

ShipWakeDomain::ShipWakeDomain(const WakeConfig& cfg, std::shared_ptr<const ShipGeometry> ship, std::shared_ptr<const ShipMotion> motion)
    : cfg_(cfg), ship_(std::move(ship)), motion_(std::move(motion)), units_(wake_units(cfg, ship_ ? ship_->datum().length : 0.0)) {
  if (!ship_ || !motion_) throw ConfigError("wake: no ship or no motion");
  if (!(cfg.smagorinsky >= 0)) throw ConfigError("wake: the Smagorinsky constant must be >= 0");
  if (cfg.fine.ratio < 0) throw ConfigError("wake: the fine region's ratio must be >= 0 (0: none), got " + std::to_string(cfg.fine.ratio));
  const double N = cfg.cells_per_length, l = ship_->datum().length;
  nx_ = static_cast<int>(std::lround(cfg.domain_length * N));
  ny_ = 2 * static_cast<int>(std::lround(0.5 * cfg.domain_width * N)) + 1;  // odd: a row of nodes on the midline
  nz_ = static_cast<int>(std::lround(cfg.domain_height * N));
  const double dx = units_.dx();
  // node (i, j, k) sits at ((i + 1/2) dx, ...) from the domain corner; the stem/waterline crossing at
  // (stem_position l, midline, (height - sea_depth) l) from the top
  const Vec3 stem_domain(cfg.stem_position * l, 0.5 * ny_ * dx, (cfg.domain_height - cfg.sea_depth) * l);
  const Vec3 stem_ship(ship_->datum().stem_x, 0.0, ship_->datum().waterline);
  origin_ = stem_ship - stem_domain + Vec3::Constant(0.5 * dx);
  hull_box_ = hull_box(*ship_);
  // the hull must stay clear of the faces
  for (const Vec3& c : hull_box_) {
    const Vec3 g = (motion_->position(c, 0.0) - origin_) / dx;
    if (g.x() < 2 || g.x() > nx_ - 3 || g.y() < 2 || g.y() > ny_ - 3 || g.z() < 2)
      throw GeometryError("wake: the ship '" + ship_->name() + "' does not fit the domain (a corner of its box at cell (" +
                          std::to_string(g.x()) + ", " + std::to_string(g.y()) + ", " + std::to_string(g.z()) + ") of " +
                          std::to_string(nx_) + " x " + std::to_string(ny_) + " x " + std::to_string(nz_) + ")");
  }
  rebuild(0.0, false);
  if (cfg.fine.enabled()) {
    fine_ = std::make_unique<FineRegion>(cfg.fine, cfg, grid(), ship_, motion_);
    const auto& lo = fine_->window_lo();
    const auto& n = fine_->window_n();
    for (int k = lo[2]; k < lo[2] + n[2]; ++k)
      for (int j = lo[1]; j < lo[1] + n[1]; ++j)
        for (int i = lo[0]; i < lo[0] + n[0]; ++i) window_cells_.push_back(static_cast<std::uint32_t>(grid().index(i, j, k)));
    if (cfg.fine.start <= 0.0) start_fine();
  }
}

void ShipWakeDomain::start_fine() {
  window_ = fine_window();
  fine_->start(window_, time());
  fine_started_ = true;
}

// The coarse air over the fine region's window (m/s, mean frame): in the fluid the lattice's, in the
// ship the hull's velocity (no-slip), in the sea the air above it (the slip sea; for interpolation the
// air just above the surface stays the air, not a layer slowed towards the sea cells).
std::vector<float> ShipWakeDomain::fine_window() {
  const std::vector<float> v = solver_->velocities(window_cells_);
  const auto& lo = fine_->window_lo();
  const auto& n = fine_->window_n();
  const double scale = units_.dx() / units_.dt(), t = time();
  const ShipPlacement place = motion_->placement(t);
  std::vector<float> w(v.size());
  std::size_t p = 0;
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i, ++p) {
        const std::size_t c = window_cells_[p];
        if (owner_[c] == kFluidNode) {
          for (int d = 0; d < 3; ++d) w[3 * p + d] = static_cast<float>(v[3 * p + d] * scale);
        } else if (owner_[c] == kShipNode) {
          const Vec3 u = motion_->velocity(place.to_body(position(lo[0] + i, lo[1] + j, lo[2] + k)), t);
          for (int d = 0; d < 3; ++d) w[3 * p + d] = static_cast<float>(u[d]);
        } else if (!cfg_.no_slip_sea && k > 0) {  // z points down: the node above is k - 1
          for (int d = 0; d < 3; ++d) w[3 * p + d] = w[3 * (p - static_cast<std::size_t>(n[0]) * n[1]) + d];
        } else if (!cfg_.no_slip_sea) {
          w[3 * p] = static_cast<float>(-cfg_.wind);
          w[3 * p + 1] = w[3 * p + 2] = 0.0f;
        } else {
          w[3 * p] = w[3 * p + 1] = w[3 * p + 2] = 0.0f;  // a no-slip sea at rest
        }
      }
  return w;
}

Vec3 ShipWakeDomain::position(int i, int j, int k) const { return origin_ + Vec3(i, j, k) * units_.dx(); }

NodeGrid ShipWakeDomain::grid() const {
  NodeGrid g;
  g.origin = origin_;
  g.dx = units_.dx();
  g.nx = nx_;
  g.ny = ny_;
  g.nz = nz_;
  return g;
}

lbm::WallMotion ShipWakeDomain::hull_motion(double t) const { return hull_wall_motion(grid(), *motion_, t, units_.dt()); }

std::vector<std::uint8_t> ShipWakeDomain::voxelise(double t) const { return voxelise_ship(grid(), *ship_, *motion_, hull_box_, t); }

void ShipWakeDomain::rebuild(double t, bool carry) {
  std::vector<std::uint8_t> owner = voxelise(t);
  voxel_time_ = t;
  if (carry && owner == owner_) return;  // the same cells: only the wall velocity changes
  lbm::LatticeConfig lc;
  lc.nx = nx_;
  lc.ny = ny_;
  lc.nz = nz_;
  lc.collision.nu = static_cast<float>(units_.lattice_viscosity());
  lc.collision.smagorinsky = static_cast<float>(cfg_.smagorinsky);
  lc.collision.model = cfg_.collision;
  lc.faces[0].type = lbm::FaceType::PressureOutlet;  // outflow at the stern end (x = 0)
  lc.faces[1].type = lbm::FaceType::VelocityInlet;   // the wind from ahead
  lc.faces[1].velocity = {static_cast<float>(-cfg_.lattice_wind), 0.0f, 0.0f};
  lc.faces[1].characteristic_inlet = cfg_.characteristic_inlet;
  lc.faces[2].type = lc.faces[3].type = lc.faces[4].type = lbm::FaceType::SlipWall;  // sides, top
  lc.faces[5].type = lbm::FaceType::Wall;                                            // below the sea
  lc.mach_guard = 0.9f;
  lbm::Lattice lat(lc);
  const bool moving = !motion_->is_static();
  const int hull = moving ? lat.add_wall_motion(hull_motion(t)) : -1;
  ship_cells_ = 0;
  for (int k = 0; k < nz_; ++k)
    for (int j = 0; j < ny_; ++j)
      for (int i = 0; i < nx_; ++i) {
        const std::uint8_t o = owner[lat.index(i, j, k)];
        if (o == kSeaNode && !cfg_.no_slip_sea) lat.set_slip_wall(i, j, k);
        if ((o == kSeaNode && cfg_.no_slip_sea) || (o == kShipNode && !moving)) lat.set_wall(i, j, k);
        if (o == kShipNode && moving) lat.set_moving_wall(i, j, k, hull);
        ship_cells_ += o == kShipNode;
      }
  if (carry) ++rebuilds_;
  if (carry && solver_ && solver_->change_walls(lat)) {  // in place (the CPU): the flow keeps its history
    owner_ = std::move(owner);
    return;
  }
  lbm::Fields carried;
  if (carry && solver_) carried = lbm::carry_flow(solver_->lattice(), solver_->fields());
  solver_ = lbm::make_solver(std::move(lat), cfg_.backend);
  owner_ = std::move(owner);
  if (!carried.rho.empty()) {
    solver_->initialize(carried.rho, carried.u);
  } else {
    std::vector<float> u(3 * cells(), 0.0f);
    for (std::size_t n = 0; n < cells(); ++n)
      if (owner_[n] == kFluidNode) u[3 * n] = static_cast<float>(-cfg_.lattice_wind);
    solver_->initialize({}, u);
  }
}

void ShipWakeDomain::step(long n) {
  using Clock = std::chrono::steady_clock;
  for (long s = 0; s < n; ++s) {
    const auto t0 = Clock::now();
    solver_->step(1);
    ++steps_;
    const double t = time();
    if (!motion_->is_static()) {
      if (hull_displacement(*motion_, hull_box_, voxel_time_, t) > cfg_.revoxelise_cells * units_.dx()) rebuild(t, true);
      solver_->set_wall_motion(0, hull_motion(t));
    }
    const auto t1 = Clock::now();
    coarse_seconds_ += std::chrono::duration<double>(t1 - t0).count();
    if (fine_ && !fine_started_ && t + 0.5 * units_.dt() >= cfg_.fine.start) {
      start_fine();
    } else if (fine_started_) {
      std::vector<float> after = fine_window();
      fine_->advance(window_, after);
      window_.swap(after);
      fine_seconds_ += std::chrono::duration<double>(Clock::now() - t1).count();
    }
  }
}

WakeTableInfo ShipWakeDomain::table_info() const {
  const double N = cfg_.cells_per_length, l = ship_->datum().length;
  const int jc = (ny_ - 1) / 2, half = static_cast<int>(std::lround(0.5 * cfg_.table_width * N));
  int i1 = std::min(nx_ - 1, static_cast<int>(std::lround((ship_->datum().stem_x - origin_.x()) / units_.dx())));
  // with a stored fine part that reaches past the stem, the table reaches as far
  if (fine_) {
    const int r = fine_->config().ratio;
    i1 = std::min(nx_ - 1, std::max(i1, fine_->window_lo()[0] + (fine_->stored_lo()[0] + fine_->stored_shape()[0] - 1) / r));
  }
  const int k0 = std::clamp(static_cast<int>(std::lround(cfg_.table_top * l / units_.dx())), 0, nz_ - 2);
  WakeTableInfo info;
  const Vec3 o = position(0, jc - half, k0);
  info.origin = {o.x(), o.y(), o.z()};
  info.spacing = units_.dx();
  info.shape = {i1 + 1, 2 * half + 1, nz_ - k0};
  info.free_stream = {-cfg_.wind, 0.0, 0.0};
  info.free_density = cfg_.density;
  info.ship = ship_->name();
  info.motion = motion_->name();
  if (fine_) {
    // the fine grid's first node is coarse node window_lo(), the stored part's stored_lo() / ratio
    // coarse nodes further; the sea face (z+: z points down) has nothing to blend with, the other five
    // are blended into the coarse grid over two coarse cells
    const int r = fine_->config().ratio;
    const std::array<int, 3>& s = fine_->stored_lo();
    info.fine.ratio = r;
    info.fine.lo = {fine_->window_lo()[0] + s[0] / r, fine_->window_lo()[1] + s[1] / r - (jc - half),
                    fine_->window_lo()[2] + s[2] / r - k0};
    info.fine.shape = fine_->stored_shape();
    info.fine.seam = {1, 1, 1, 1, 1, 0};
    info.fine.seam_cells = 2;
    // the table stores the fine grid inside its coarse box
    for (int d = 0; d < 3; ++d)
      if (info.fine.lo[d] < 0 || info.fine.lo[d] + (info.fine.shape[d] - 1) / info.fine.ratio > info.shape[d] - 1)
        throw GeometryError("wake: the fine region reaches outside the tabulated region (x from the outflow face forward, |y| <= " +
                            std::to_string(0.5 * cfg_.table_width) + " ship lengths, from " + std::to_string(cfg_.table_top) +
                            " ship lengths below the top down); shrink it or widen the table");
  }
  return info;
}

bool ShipWakeDomain::velocity_at(const lbm::Fields& f, const Vec3& p, std::array<double, 3>& u) const {
  return fluid_velocity_at(grid(), owner_, f.u.data(), units_.dx() / units_.dt(), p, u);
}

void ShipWakeDomain::table_frame(const lbm::Fields& f, std::vector<float>& velocity, std::vector<float>& density) const {
  const WakeTableInfo info = table_info();
  const double scale = units_.dx() / units_.dt();
  const int jc = (ny_ - 1) / 2, j0 = jc - (info.shape[1] - 1) / 2, k0 = nz_ - info.shape[2];
  velocity.assign(3 * info.points(), 0.0f);
  density.assign(info.points(), static_cast<float>(cfg_.density));
  const double t = time();
  const ShipPlacement place = motion_->placement(t);
  std::size_t p = 0;
  for (int k = k0; k < nz_; ++k)
    for (int j = j0; j < j0 + info.shape[1]; ++j)
      for (int i = 0; i < info.shape[0]; ++i, ++p) {
        const std::size_t n = i + static_cast<std::size_t>(nx_) * (j + static_cast<std::size_t>(ny_) * k);
        if (owner_[n] == kFluidNode) {
          for (int d = 0; d < 3; ++d) velocity[3 * p + d] = static_cast<float>(f.u[3 * n + d] * scale);
          density[p] = static_cast<float>(f.rho[n] * cfg_.density);
        } else if (owner_[n] == kShipNode) {
          const Vec3 v = motion_->velocity(place.to_body(position(i, j, k)), t);
          for (int d = 0; d < 3; ++d) velocity[3 * p + d] = static_cast<float>(v[d]);
        }
      }
}

namespace {
// The plane of nodes j (y = 0) of a grid: the fluid's velocity (lattice velocities times scale) and
// the solid flag; solids at rest in the plane's statistics.
PlaneSample node_plane(const NodeGrid& g, int j, const std::vector<std::uint8_t>& owner, const lbm::Fields& f, double scale) {
  PlaneSample pl;
  pl.nx = g.nx;
  pl.nz = g.nz;
  pl.u.resize(3 * static_cast<std::size_t>(g.nx) * g.nz);
  pl.solid.resize(static_cast<std::size_t>(g.nx) * g.nz);
  for (int i = 0; i < g.nx; ++i) pl.x.push_back(g.position(i, j, 0).x());
  for (int k = 0; k < g.nz; ++k) pl.z.push_back(g.position(0, j, k).z());
  for (int k = 0; k < g.nz; ++k)
    for (int i = 0; i < g.nx; ++i) {
      const std::size_t n = g.index(i, j, k), p = i + static_cast<std::size_t>(g.nx) * k;
      pl.solid[p] = owner[n] != kFluidNode;
      for (int d = 0; d < 3; ++d) pl.u[3 * p + d] = pl.solid[p] ? 0.0f : static_cast<float>(f.u[3 * n + d] * scale);
    }
  return pl;
}
}  // namespace

ShipWakeDomain::Plane ShipWakeDomain::centre_plane(const lbm::Fields& f) const {
  return node_plane(grid(), (ny_ - 1) / 2, owner_, f, units_.dx() / units_.dt());
}

ShipWakeDomain::Plane ShipWakeDomain::fine_centre_plane(const lbm::Fields& f) const {
  if (!fine_) return {};
  const NodeGrid& g = fine_->grid();
  const int j = static_cast<int>(std::lround(-g.origin.y() / g.dx));  // the fine grid's row at y = 0
  return node_plane(g, j, fine_->owner(), f, fine_->units().dx() / fine_->units().dt());
}

ShipWakeDomain::State ShipWakeDomain::state() {
  State s;
  s.steps = steps_;
  s.voxel_time = voxel_time_;
  s.populations = solver_->populations();
  s.solver_steps = solver_->steps_done();
  if (fine_) {
    s.has_fine = true;
    s.fine_started = fine_started_;
    s.fine = fine_->state();
  }
  return s;
}

void ShipWakeDomain::restore(const State& s) {
  if (s.steps < 0) throw ConfigError("wake: checkpoint with a negative step count");
  if (s.has_fine != static_cast<bool>(fine_))
    throw ConfigError(std::string("wake: a checkpoint ") + (s.has_fine ? "with" : "without") + " a fine region for a domain " +
                      (fine_ ? "with" : "without") + " one");
  owner_.clear();
  rebuild(s.voxel_time, false);
  solver_->restore(s.solver_steps, s.populations);
  steps_ = s.steps;
  if (!motion_->is_static()) solver_->set_wall_motion(0, hull_motion(time()));
  if (fine_) {
    fine_->restore(s.fine);
    fine_started_ = s.fine_started;
    window_ = fine_window();
  }
}

}  // namespace ship_lrm::wake
