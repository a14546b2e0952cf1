// A fine region inside the ship-wake domain, by one-way nesting (docs/design.md, "A fine region by
// one-way nesting"): a box of the ship's mean frame around the aft superstructure, the hangar, the
// flight deck and the approach path, at `ratio` times the wake domain's resolution, run as an LBM
// domain of its own inside the coarse one. Its fore and side faces take the coarse domain's air
// (characteristic velocity inlets), its top and aft faces are impedance outlets with the coarse air as
// their reference (the faces the LRM has inside a wake table); the ship and the sea are voxelised at
// the fine resolution. The faces are fed at every fine step from the coarse field, trilinear in space
// and linear in time between two coarse steps, with the same per-cell functions as the LRM's feed
// (lbm/grid_feed.hpp). Acoustic scaling: the same lattice wind, dx and dt both divided by the ratio,
// so the region runs `ratio` steps per coarse step. Nothing flows back into the coarse domain.
#pragma once
#include <array>
#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

#include "ship_lrm/lbm/solver.hpp"
#include "ship_lrm/lbm/units.hpp"
#include "ship_lrm/wake/ship_voxels.hpp"

namespace ship_lrm::wake {

struct WakeConfig;

struct FineRegionConfig {
  int ratio = 0;  // fine cells per coarse cell (1 .. 16); 0: no fine region
  // The box, in ship lengths: x from `aft` to `fore` (ship frame, forward from the hangar door),
  // |y| up to `half_width`, from `top` above the waterline down to the first coarse node in the sea.
  double aft = -0.42, fore = 0.35, half_width = 0.15, top = 0.3;
  // When the region starts (s), from the coarse air then: before it the coarse domain runs alone,
  // so that a long start-up costs only the coarse steps (the region then needs a few of its own
  // flow-through times to develop its turbulence).
  double start = 0;
  // The part of the box the table stores (ship lengths, as aft, fore and top; NaN: the box's own).
  // The region must reach over what sheds the deck's turbulence (the whole superstructure: an aft
  // box fed the coarse domain's steady wake stays laminar, docs/validation.md "The NRC deck case");
  // the table needs only what the rotor flies through (the deck and the approach behind it), a
  // fraction of the region's size on disk. Snapped outwards to coarse nodes, within the box.
  double stored_aft = std::numeric_limits<double>::quiet_NaN();
  double stored_fore = std::numeric_limits<double>::quiet_NaN();
  double stored_top = std::numeric_limits<double>::quiet_NaN();
  bool enabled() const { return ratio > 0; }
};

class FineRegion {
 public:
  // coarse: the wake domain's nodes (its dx and node positions); wake: its configuration (wind,
  // lattice wind, viscosity, Smagorinsky, collision, backend, sea), cfg.cells_per_length the coarse N.
  // Throws ConfigError for a bad ratio or box, GeometryError for a box that leaves the coarse
  // domain (two coarse cells from its faces) or whose faces cut the ship (only a static ship may cross
  // the fore face; every other face keeps two coarse cells clear of it at all times).
  FineRegion(const FineRegionConfig& cfg, const WakeConfig& wake, const NodeGrid& coarse, std::shared_ptr<const ShipGeometry> ship,
             std::shared_ptr<const ShipMotion> motion);
  const FineRegionConfig& config() const { return cfg_; }
  const NodeGrid& grid() const { return grid_; }  // fine node (0, 0, 0) is coarse node window_lo()
  const lbm::UnitConverter& units() const { return units_; }
  // The coarse nodes the faces are fed from: the box [window_lo, window_lo + window_n) of coarse
  // indices. Its velocities (m/s, mean frame, 3 per node, x fastest) are what start and advance take.
  const std::array<int, 3>& window_lo() const { return lo_; }
  const std::array<int, 3>& window_n() const { return n_; }
  std::size_t window_points() const { return static_cast<std::size_t>(n_[0]) * n_[1] * n_[2]; }
  // Every fluid node starts at equilibrium with the coarse window's air interpolated to it, time t.
  void start(const std::vector<float>& window, double t);
  // One coarse step, the coarse air at its start (`before`: the previous call's `after`, or start's
  // window) and end (`after`): `ratio` fine steps, fine step s (1 .. ratio) fed at its own start
  // time, weight (s - 1) / ratio on `after`.
  void advance(const std::vector<float>& before, const std::vector<float>& after);
  double time() const { return time_; }
  long steps() const { return steps_; }
  std::size_t rebuilds() const { return rebuilds_; }
  lbm::Solver& solver() { return *solver_; }
  lbm::Fields fields() { return solver_->fields(); }
  const std::vector<std::uint8_t>& owner() const { return owner_; }  // kFluidNode, kSeaNode, kShipNode per fine node
  // The stored part of the fine grid (FineRegionConfig::stored_*): fine nodes [stored_lo, stored_lo +
  // stored_shape) of grid(), stored_lo a multiple of the ratio on every axis (a coarse node).
  const std::array<int, 3>& stored_lo() const { return stored_lo_; }
  const std::array<int, 3>& stored_shape() const { return stored_shape_; }
  std::size_t stored_points() const { return static_cast<std::size_t>(stored_shape_[0]) * stored_shape_[1] * stored_shape_[2]; }
  // The stored part of the fine grid in physical units from `f` (fields()), as the table's fine level stores it:
  // velocity (m/s, mean frame, 3 per node, x fastest), density (kg/m^3: the lattice density times
  // `free_density`); inside the ship its velocity, in the sea at rest, both at the free density.
  void table_frame(const lbm::Fields& f, double free_density, std::vector<float>& velocity, std::vector<float>& density) const;
  // Velocity (m/s, mean frame) at ship-frame point p from `f`, trilinear between the fine nodes;
  // false outside the fine grid or where the node nearest p is not fluid (fluid_velocity_at).
  bool velocity_at(const lbm::Fields& f, const Vec3& p, std::array<double, 3>& u) const;

  // Checkpoint (see ShipWakeDomain::State): with the open faces' memory, so that a restored region
  // continues bit for bit.
  struct State {
    double time = 0;
    long steps = 0, solver_steps = 0;
    double voxel_time = 0;
    std::vector<float> populations;
    lbm::Solver::OpenBoundaryState faces;
  };
  State state();
  void restore(const State& s);

 private:
  FineRegionConfig cfg_;
  std::shared_ptr<const ShipGeometry> ship_;
  std::shared_ptr<const ShipMotion> motion_;
  NodeGrid coarse_, grid_;
  lbm::UnitConverter units_;
  float lattice_wind_;
  float smagorinsky_;
  lbm::CollisionModel collision_;
  lbm::Backend backend_;
  bool no_slip_sea_;
  double revoxelise_cells_;
  std::array<int, 3> lo_{}, n_{};
  std::array<int, 3> stored_lo_{}, stored_shape_{};  // fine nodes
  std::array<Vec3, 8> hull_box_{};
  double time_ = 0, voxel_time_ = 0;
  long steps_ = 0;
  std::size_t rebuilds_ = 0;
  std::vector<std::uint8_t> owner_;
  std::unique_ptr<lbm::Solver> solver_;
  lbm::GridFeed feed_;
  std::uint64_t serial_ = 0;  // of the last window handed over (a device copies a window once per serial)
  void check_window(const std::vector<float>& w) const;
  void check_ship_clearance() const;
  void rebuild(double t, bool carry);
  lbm::GridWindowView view(const std::vector<float>& w) const;
};

}  // namespace ship_lrm::wake
