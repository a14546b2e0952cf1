// A fine region inside the ship-wake domain by one-way nesting (see fine_region.hpp).
#include "ship_lrm/wake/fine_region.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "ship_lrm/lbm/grid_feed.hpp"
#include "ship_lrm/lbm/refill.hpp"
#include "ship_lrm/wake/wake_domain.hpp"

namespace ship_lrm::wake {
namespace {

constexpr int kMaxRatio = 16;
constexpr double kClearCoarseCells = 2.0;  // faces other than a static ship's fore face keep this far from the ship

std::string metres(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.3f m", v);
  return b;
}

WakeConfig fine_wake_config(const WakeConfig& wake, int ratio) {
  WakeConfig c = wake;
  c.cells_per_length = wake.cells_per_length * ratio;
  return c;
}

}  // namespace

FineRegion::FineRegion(const FineRegionConfig& cfg, const WakeConfig& wake, const NodeGrid& coarse,
                       std::shared_ptr<const ShipGeometry> ship, std::shared_ptr<const ShipMotion> motion)
    : cfg_(cfg),
      ship_(std::move(ship)),
      motion_(std::move(motion)),
      coarse_(coarse),
      units_(wake_units(fine_wake_config(wake, cfg.ratio > 0 ? cfg.ratio : 1), ship_ ? ship_->datum().length : 0.0)),
      lattice_wind_(static_cast<float>(wake.lattice_wind)),
      smagorinsky_(static_cast<float>(wake.smagorinsky)),
      collision_(wake.collision),
      backend_(wake.backend),
      no_slip_sea_(wake.no_slip_sea),
      revoxelise_cells_(wake.revoxelise_cells) {
  if (!ship_ || !motion_) throw ConfigError("fine region: no ship or no motion");
  if (cfg.ratio < 1 || cfg.ratio > kMaxRatio)
    throw ConfigError("fine region: the refinement ratio must be 1 .. " + std::to_string(kMaxRatio) + " fine cells per coarse cell, got " +
                      std::to_string(cfg.ratio));
  for (double v : {cfg.aft, cfg.fore, cfg.half_width, cfg.top})
    if (!std::isfinite(v)) throw ConfigError("fine region: the box must be finite");
  if (!(cfg.start >= 0) || !std::isfinite(cfg.start)) throw ConfigError("fine region: its start time must be >= 0 s");
  if (!(cfg.fore > cfg.aft) || !(cfg.half_width > 0) || !(cfg.top > 0))
    throw ConfigError("fine region: the box needs fore > aft, a half width > 0 and a top > 0 above the waterline (ship lengths)");
  const double l = ship_->datum().length, dx = coarse.dx, water = ship_->datum().waterline;
  const int jc = (coarse.ny - 1) / 2, half = static_cast<int>(std::ceil(cfg.half_width * l / dx - 1e-9));
  const int i0 = static_cast<int>(std::floor((cfg.aft * l - coarse.origin.x()) / dx + 1e-9));
  const int i1 = static_cast<int>(std::ceil((cfg.fore * l - coarse.origin.x()) / dx - 1e-9));
  const int k0 = static_cast<int>(std::floor((water - cfg.top * l - coarse.origin.z()) / dx + 1e-9));
  const int k1 = static_cast<int>(std::floor((water - coarse.origin.z()) / dx)) + 1;  // the first coarse node in the sea
  const int j0 = jc - half, j1 = jc + half;
  const std::string box = "x " + metres(cfg.aft * l) + " .. " + metres(cfg.fore * l) + ", |y| <= " + metres(cfg.half_width * l) + ", " +
                          metres(cfg.top * l) + " above the waterline";
  // two coarse cells from every coarse face, and one more node for the interpolation's last cell
  if (i0 < 2 || i1 + 1 > coarse.nx - 3 || j0 < 2 || j1 + 1 > coarse.ny - 3 || k0 < 2 || k1 + 1 > coarse.nz - 1)
    throw GeometryError("fine region (" + box +
                        ") does not fit inside the wake domain with two coarse cells to its faces (coarse cells x " + std::to_string(i0) +
                        " .. " + std::to_string(i1) + " of " + std::to_string(coarse.nx) + ", y " + std::to_string(j0) + " .. " +
                        std::to_string(j1) + " of " + std::to_string(coarse.ny) + ", z " + std::to_string(k0) + " .. " +
                        std::to_string(k1) + " of " + std::to_string(coarse.nz) + ")");
  if (i1 - i0 < 4 || half < 2 || k1 - k0 < 4) throw ConfigError("fine region (" + box + ") spans fewer than 4 coarse cells along an axis");
  lo_ = {i0, j0, k0};
  n_ = {i1 - i0 + 2, j1 - j0 + 2, k1 - k0 + 2};
  grid_.origin = coarse.position(i0, j0, k0);
  grid_.dx = dx / cfg.ratio;
  grid_.nx = cfg.ratio * (i1 - i0) + 1;
  grid_.ny = cfg.ratio * (j1 - j0) + 1;
  grid_.nz = cfg.ratio * (k1 - k0) + 1;
  // the stored part: coarse cells [s0, s1] of each axis (y: the whole width), outwards to coarse nodes
  const auto stored_value = [](double v, double box) { return std::isnan(v) ? box : v; };
  const double s_aft = stored_value(cfg.stored_aft, cfg.aft), s_fore = stored_value(cfg.stored_fore, cfg.fore);
  const double s_top = stored_value(cfg.stored_top, cfg.top);
  const double eps = 1e-9;
  if (!std::isfinite(s_aft) || !std::isfinite(s_fore) || !std::isfinite(s_top) || s_aft < cfg.aft - eps || s_fore > cfg.fore + eps ||
      !(s_fore > s_aft) || !(s_top > 0) || s_top > cfg.top + eps)
    throw ConfigError("fine region: the stored part (x " + metres(s_aft * l) + " .. " + metres(s_fore * l) + ", " + metres(s_top * l) +
                      " above the waterline) must lie inside the box (" + box + ") with fore > aft and a top > 0");
  const int si0 = std::max(i0, static_cast<int>(std::floor((s_aft * l - coarse.origin.x()) / dx + eps)));
  const int si1 = std::min(i1, static_cast<int>(std::ceil((s_fore * l - coarse.origin.x()) / dx - eps)));
  const int sk0 = std::max(k0, static_cast<int>(std::floor((water - s_top * l - coarse.origin.z()) / dx + eps)));
  if (si1 - si0 < 4 || k1 - sk0 < 4)
    throw ConfigError("fine region: the stored part spans fewer than 4 coarse cells along x or z (x " + metres(s_aft * l) + " .. " +
                      metres(s_fore * l) + ", " + metres(s_top * l) +
                      " above the waterline): the table blends it into the coarse "
                      "grid over 2 coarse cells at each face");
  stored_lo_ = {cfg.ratio * (si0 - i0), 0, cfg.ratio * (sk0 - k0)};
  stored_shape_ = {cfg.ratio * (si1 - si0) + 1, grid_.ny, cfg.ratio * (k1 - sk0) + 1};
  hull_box_ = hull_box(*ship_);
  check_ship_clearance();
  // the feed: the coarse grid as the field, the fine node (0, 0, 0) as the "hub", axes aligned, at rest
  for (int d = 0; d < 3; ++d) {
    feed_.origin[d] = coarse.origin[d];
    feed_.hub[d] = grid_.origin[d];
  }
  feed_.spacing = dx;
  feed_.shape[0] = coarse.nx;
  feed_.shape[1] = coarse.ny;
  feed_.shape[2] = coarse.nz;
  feed_.free_stream[0] = static_cast<float>(-wake.wind);
  feed_.to_lattice = units_.dt() / units_.dx();
  feed_.dx = grid_.dx;
  feed_.centre = 0;
  rebuild(0.0, false);
}

void FineRegion::check_ship_clearance() const {
  const ShipGeometry& ship = *ship_;
  const double dx = coarse_.dx, clear = kClearCoarseCells * dx, water = ship.datum().waterline;
  std::vector<double> times{0.0};
  if (!motion_->is_static())
    for (int s = 1; s <= 400; ++s) times.push_back(0.05 * s);  // 20 s: a period of the wind-tunnel and approach motions
  const char* names[6] = {"aft", "fore", "port", "starboard", "top", "bottom"};
  const int last[3] = {n_[0] - 2, n_[1] - 2, n_[2] - 2};  // coarse cells along each axis
  bool crosses_fore = false;
  for (int face = 0; face < 5; ++face) {
    const int axis = face / 2;
    const int a = (axis + 1) % 3, b = (axis + 2) % 3;
    for (int u = 0; u <= last[a]; ++u)
      for (int v = 0; v <= last[b]; ++v) {
        int c[3];
        c[axis] = face % 2 ? last[axis] : 0;
        c[a] = u;
        c[b] = v;
        const Vec3 p = coarse_.position(lo_[0] + c[0], lo_[1] + c[1], lo_[2] + c[2]);
        if (p.z() > water) continue;  // the sea, not the ship
        for (double t : times) {
          const double d = ship.signed_distance(motion_->placement(t).to_body(p));
          if (d >= clear) continue;
          if (face == 1) {
            crosses_fore = true;
            break;
          }
          throw GeometryError("fine region: its " + std::string(names[face]) + " face cuts the ship or passes within " +
                              std::to_string(kClearCoarseCells) + " coarse cells of it (at x " + metres(p.x()) + ", y " + metres(p.y()) +
                              ", z " + metres(p.z()) + ", t " + std::to_string(t) + " s); move it clear");
        }
      }
  }
  if (crosses_fore && !motion_->is_static())
    throw GeometryError("fine region: a moving ship may not cross its fore face; extend the region past the bow (fore >= " +
                        std::to_string((ship.datum().stem_x + clear) / ship.datum().length) + " ship lengths)");
}

lbm::GridWindowView FineRegion::view(const std::vector<float>& w) const {
  lbm::GridWindowView v;
  for (int d = 0; d < 3; ++d) {
    v.lo[d] = lo_[d];
    v.n[d] = n_[d];
  }
  v.u = w.data();
  return v;
}

void FineRegion::check_window(const std::vector<float>& w) const {
  if (w.size() != 3 * window_points())
    throw ConfigError("fine region: a coarse window of " + std::to_string(w.size()) + " values, expected " +
                      std::to_string(3 * window_points()));
}

void FineRegion::rebuild(double t, bool carry) {
  std::vector<std::uint8_t> owner = voxelise_ship(grid_, *ship_, *motion_, hull_box_, t);
  voxel_time_ = t;
  if (carry && owner == owner_) return;
  lbm::LatticeConfig lc;
  lc.nx = grid_.nx;
  lc.ny = grid_.ny;
  lc.nz = grid_.nz;
  lc.collision.nu = static_cast<float>(units_.lattice_viscosity());
  lc.collision.smagorinsky = smagorinsky_;
  lc.collision.model = collision_;
  // the coarse air comes in at the fore face and the sides (x = last, y = 0 and last) and leaves
  // through the aft face and the top (x = 0, z = 0: z points down), as at the LRM's faces in a table
  for (int f : {1, 2, 3}) {
    lc.faces[f].type = lbm::FaceType::VelocityInlet;
    lc.faces[f].velocity = {-lattice_wind_, 0.0f, 0.0f};
    lc.faces[f].characteristic_inlet = true;
  }
  for (int f : {0, 4}) {
    lc.faces[f].type = lbm::FaceType::ImpedanceOutlet;
    lc.faces[f].velocity = {-lattice_wind_, 0.0f, 0.0f};
    lc.faces[f].inflow_from_reference = true;
  }
  lc.faces[5].type = lbm::FaceType::Wall;  // below the sea
  lc.mach_guard = 0.9f;
  lbm::Lattice lat(lc);
  const bool moving = !motion_->is_static();
  const int hull = moving ? lat.add_wall_motion(hull_wall_motion(grid_, *motion_, t, units_.dt())) : -1;
  for (int k = 0; k < grid_.nz; ++k)
    for (int j = 0; j < grid_.ny; ++j)
      for (int i = 0; i < grid_.nx; ++i) {
        const std::uint8_t o = owner[grid_.index(i, j, k)];
        if (o == kSeaNode && !no_slip_sea_) lat.set_slip_wall(i, j, k);
        if ((o == kSeaNode && no_slip_sea_) || (o == kShipNode && !moving)) lat.set_wall(i, j, k);
        if (o == kShipNode && moving) lat.set_moving_wall(i, j, k, hull);
      }
  if (carry) ++rebuilds_;
  if (carry && solver_ && solver_->change_walls(lat)) {
    owner_ = std::move(owner);
    return;
  }
  lbm::Fields carried;
  if (carry && solver_) carried = lbm::carry_flow(solver_->lattice(), solver_->fields());
  solver_ = lbm::make_solver(std::move(lat), backend_);
  owner_ = std::move(owner);
  if (!carried.rho.empty()) {
    solver_->initialize(carried.rho, carried.u);
  } else {
    std::vector<float> u(3 * grid_.cells(), 0.0f);
    for (std::size_t n = 0; n < grid_.cells(); ++n)
      if (owner_[n] == kFluidNode) u[3 * n] = -lattice_wind_;
    solver_->initialize({}, u);
  }
}

void FineRegion::start(const std::vector<float>& window, double t) {
  check_window(window);
  const lbm::GridWindowView w = view(window);
  lbm::GridFeed f = feed_;
  f.weight1 = 0;
  std::vector<float> u(3 * grid_.cells(), 0.0f);
  for (int k = 0; k < grid_.nz; ++k)
    for (int j = 0; j < grid_.ny; ++j)
      for (int i = 0; i < grid_.nx; ++i) {
        const std::size_t n = grid_.index(i, j, k);
        if (owner_[n] != kFluidNode) continue;
        const Vec3 p = grid_.position(i, j, k);
        const double pp[3] = {p.x(), p.y(), p.z()};
        float v[3];
        lbm::grid_velocity(f, w, w, pp, v);
        for (int d = 0; d < 3; ++d) u[3 * n + d] = static_cast<float>(v[d] * feed_.to_lattice);
      }
  // the faces first: the start from this state then leaves the impedance outlets no reference change
  // to follow (Solver::initialize), as the state is their reference's
  feed_.weight1 = 0;
  serial_ = 1;
  solver_->feed_faces_from_grid(w, serial_, w, serial_, feed_);
  solver_->initialize({}, u);  // ConfigError beyond the Mach limit
  time_ = t;
}

void FineRegion::advance(const std::vector<float>& before, const std::vector<float>& after) {
  check_window(before);
  check_window(after);
  const lbm::GridWindowView w0 = view(before), w1 = view(after);
  // `before` is the last call's `after`: a device copies each window once, not at every fine step
  const std::uint64_t s0 = serial_, s1 = ++serial_;
  for (int s = 1; s <= cfg_.ratio; ++s) {
    feed_.weight1 = static_cast<double>(s - 1) / cfg_.ratio;
    solver_->feed_faces_from_grid(w0, s0, w1, s1, feed_);
    solver_->step(1);
    ++steps_;
    time_ += units_.dt();
    if (motion_->is_static()) continue;
    if (hull_displacement(*motion_, hull_box_, voxel_time_, time_) > revoxelise_cells_ * grid_.dx) rebuild(time_, true);
    solver_->set_wall_motion(0, hull_wall_motion(grid_, *motion_, time_, units_.dt()));
  }
}

void FineRegion::table_frame(const lbm::Fields& f, double free_density, std::vector<float>& velocity, std::vector<float>& density) const {
  const double scale = units_.dx() / units_.dt();
  const std::size_t n = stored_points();
  velocity.assign(3 * n, 0.0f);
  density.assign(n, static_cast<float>(free_density));
  const ShipPlacement place = motion_->placement(time_);
  std::size_t s = 0;  // the stored point, x fastest
  for (int k = stored_lo_[2]; k < stored_lo_[2] + stored_shape_[2]; ++k)
    for (int j = stored_lo_[1]; j < stored_lo_[1] + stored_shape_[1]; ++j)
      for (int i = stored_lo_[0]; i < stored_lo_[0] + stored_shape_[0]; ++i, ++s) {
        const std::size_t c = grid_.index(i, j, k);
        if (owner_[c] == kFluidNode) {
          for (int d = 0; d < 3; ++d) velocity[3 * s + d] = static_cast<float>(f.u[3 * c + d] * scale);
          density[s] = static_cast<float>(f.rho[c] * free_density);
        } else if (owner_[c] == kShipNode) {
          const Vec3 v = motion_->velocity(place.to_body(grid_.position(i, j, k)), time_);
          for (int d = 0; d < 3; ++d) velocity[3 * s + d] = static_cast<float>(v[d]);
        }
      }
}

bool FineRegion::velocity_at(const lbm::Fields& f, const Vec3& p, std::array<double, 3>& u) const {
  return fluid_velocity_at(grid_, owner_, f.u.data(), units_.dx() / units_.dt(), p, u);
}

FineRegion::State FineRegion::state() {
  State s;
  s.time = time_;
  s.steps = steps_;
  s.voxel_time = voxel_time_;
  s.populations = solver_->populations();
  s.solver_steps = solver_->steps_done();
  s.faces = solver_->open_boundary_state();
  return s;
}

void FineRegion::restore(const State& s) {
  if (s.steps < 0) throw ConfigError("fine region: checkpoint with a negative step count");
  owner_.clear();
  rebuild(s.voxel_time, false);
  solver_->restore(s.solver_steps, s.populations);
  solver_->restore_open_boundary_state(s.faces);
  steps_ = s.steps;
  time_ = s.time;
  if (!motion_->is_static()) solver_->set_wall_motion(0, hull_wall_motion(grid_, *motion_, time_, units_.dt()));
}

}  // namespace ship_lrm::wake
