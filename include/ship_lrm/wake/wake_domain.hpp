// The ship-wake domain (thesis 6.2): a lattice-Boltzmann box around the ship, 4 l long,
// 1.5 l wide and 0.88 l high (l: ship length), the stem at 3.25 l from the outflow, the waterline
// 0.088 l above the floor, the ship centred across. Inflow at the bow end (velocity inlet, the wind
// from ahead), outflow at the stern end (pressure outlet), slip walls at the sides and the top,
// no-slip sea surface and hull, Smagorinsky s = 0.025.
//
// Frame: the thesis fixes the grid to the moving ship (ALE). Here the grid stays in the ship's mean
// frame (moving with its mean speed, not with its heave, roll and pitch), and the hull moves through
// it as a moving no-slip wall (Ladd's moving bounce-back), re-voxelised when it has moved by a
// quarter cell: in place on the CPU (lbm::Solver::change_walls), else a new solver with the flow of
// lbm::carry_flow; cells that left the hull are refilled either way. The sea surface, the faces and the table's grid
// then never move: a table point is a fixed point of the mean frame, and the wake server needs no
// ship attitude to look it up (the LRM gets the ship's walls from the ship geometry and motion).
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "ship_lrm/lbm/solver.hpp"
#include "ship_lrm/lbm/units.hpp"
#include "ship_lrm/wake/fine_region.hpp"
#include "ship_lrm/wake/ship_geometry.hpp"
#include "ship_lrm/wake/ship_motion.hpp"
#include "ship_lrm/wake/ship_voxels.hpp"
#include "ship_lrm/wake/wake_statistics.hpp"
#include "ship_lrm/wake/wake_table.hpp"

namespace ship_lrm::wake {

struct WakeConfig {
  int cells_per_length = 48;  // N_ship: cells per ship length (the thesis converges at 364)
  double wind = 20.58;        // m/s, wind over the deck from ahead (thesis 9.1: 20.58 full scale, 7: 9.77 model)
  // The wind in lattice units: Mach 0.078, the thesis' full-scale value (0.3 c_s at 80 m/s). BGK +
  // Smagorinsky at the wake's tau is unstable from Mach 0.15 - 0.16 (`ship_lrm validate
  // stream-stability`); at 0.1 (Mach 0.17, the default until 2026-12-04) the ship seeded a growing
  // noise at the inlet (docs/design.md, "A characteristic inlet").
  double lattice_wind = 0.045;
  double viscosity = 1.46072e-4;  // m^2/s (thesis tables 6.2, 6.3)
  double density = 1.1934;        // kg/m^3 (1.225 for the model, table 6.2)
  double smagorinsky = 0.025;     // thesis 6.2
  // BGK (the thesis') or the recursive regularised collision, stable at the wake's tau to Mach 0.3
  lbm::CollisionModel collision = lbm::CollisionModel::Bgk;
  // The wind's face as a characteristic inlet (lbm::FaceCondition::characteristic_inlet): waves from
  // the ship leave through it instead of being reflected. The thesis' reflecting inlet with the outlet
  // opposite lets a disturbed stream grow (docs/design.md, "A characteristic inlet", 2026-12-04).
  bool characteristic_inlet = true;
  lbm::Backend backend = lbm::Backend::Auto;
  // domain, in ship lengths (thesis 6.2)
  double domain_length = 4.0, domain_width = 1.5, domain_height = 0.88;
  double stem_position = 3.25;  // stem / waterline crossing from the outflow face
  double sea_depth = 0.088;     // waterline above the floor
  // tabulated region (thesis 6.3): x from the outflow face to the stem, this wide about the midline,
  // from this far below the top down to the floor
  double table_width = 0.6, table_top = 0.24;
  double revoxelise_cells = 0.25;  // hull displacement (cells) that triggers a re-voxelisation
  // Sea surface: slip (default) or no-slip (the thesis). A uniform inflow meeting a no-slip floor at
  // the inlet is a singular corner; at our resolutions (tau - 1/2 ~ 1e-4) it went unstable there
  // (model case, N = 48, after 5000 steps). The wind over the sea is an atmospheric profile, not a
  // boundary layer grown from the inlet; the slip surface keeps the inflow as given.
  bool no_slip_sea = false;
  // A finer nested box around the aft superstructure, the deck and the approach path (fine_region.hpp):
  // off while fine.ratio is 0.
  FineRegionConfig fine;
};

class ShipWakeDomain {
 public:
  // Throws ConfigError for bad values, GeometryError when the ship does not fit the domain.
  ShipWakeDomain(const WakeConfig& cfg, std::shared_ptr<const ShipGeometry> ship, std::shared_ptr<const ShipMotion> motion);
  const WakeConfig& config() const { return cfg_; }
  const lbm::UnitConverter& units() const { return units_; }
  int nx() const { return nx_; }
  int ny() const { return ny_; }
  int nz() const { return nz_; }
  std::size_t cells() const { return static_cast<std::size_t>(nx_) * ny_ * nz_; }
  double time() const { return steps_ * units_.dt(); }
  long steps() const { return steps_; }
  std::size_t rebuilds() const { return rebuilds_; }
  std::size_t ship_cells() const { return ship_cells_; }
  lbm::Solver& solver() { return *solver_; }
  // Ship-frame position (mean pose) of lattice node (i, j, k), and the grid of all nodes.
  Vec3 position(int i, int j, int k) const;
  NodeGrid grid() const;
  // Advance n steps; the hull moves with the ship motion, and the fine region (if any) follows each
  // step with its own `ratio` steps, fed from this domain's air.
  void step(long n = 1);
  // The fine region, or null without one (WakeConfig::fine); fine_started(): it runs (from
  // FineRegionConfig::start on; before, its fields are its unstarted lattice's).
  FineRegion* fine() { return fine_.get(); }
  const FineRegion* fine() const { return fine_.get(); }
  bool fine_started() const { return fine_started_; }
  // Wall-clock seconds spent in each level's steps so far (the fine level's with its face feed).
  double coarse_seconds() const { return coarse_seconds_; }
  double fine_seconds() const { return fine_seconds_; }

  // The lattice fields now (one copy serves table_frame and centre_plane in the same step).
  lbm::Fields fields() { return solver_->fields(); }
  // The tabulated region (grid = lattice nodes; with a fine region its level in `fine`) and one frame of it in physical units from `f`
  // (fields()): velocity (3 per point) in m/s in the mean frame, density in kg/m^3; inside solids the
  // body's velocity and the free density.
  WakeTableInfo table_info() const;  // GeometryError when the fine region reaches outside the tabulated region
  void table_frame(const lbm::Fields& f, std::vector<float>& velocity, std::vector<float>& density) const;
  // Velocity (m/s, mean frame) at ship-frame point p from `f` (fields()), trilinear between nodes;
  // false outside the domain or at a solid (see fluid_velocity_at).
  bool velocity_at(const lbm::Fields& f, const Vec3& p, std::array<double, 3>& u) const;
  // The centre plane y = 0: velocity (m/s, 3 per point, x fastest then z) and a solid flag; the fine
  // region's from its fields (`f`: fine()->fields()).
  using Plane = PlaneSample;
  Plane centre_plane(const lbm::Fields& f) const;
  Plane fine_centre_plane(const lbm::Fields& f) const;

  // Checkpoint: the step count, the pose the walls were voxelised at and the populations. restore()
  // re-voxelises at that pose and puts the populations back (ConfigError when they do not fit).
  struct State {
    long steps = 0;
    long solver_steps = 0;  // since the lattice was last built (the population layout's parity)
    double voxel_time = 0;
    std::vector<float> populations;
    bool has_fine = false, fine_started = false;
    FineRegion::State fine;
  };
  State state();
  void restore(const State& s);

 private:
  WakeConfig cfg_;
  std::shared_ptr<const ShipGeometry> ship_;
  std::shared_ptr<const ShipMotion> motion_;
  lbm::UnitConverter units_;
  int nx_, ny_, nz_;
  Vec3 origin_;  // ship-frame position of node (0, 0, 0)
  long steps_ = 0;
  double voxel_time_ = 0;
  std::size_t rebuilds_ = 0, ship_cells_ = 0;
  double coarse_seconds_ = 0, fine_seconds_ = 0;
  bool fine_started_ = false;
  std::array<Vec3, 8> hull_box_;     // corners of the hull's box (ship frame)
  std::vector<std::uint8_t> owner_;  // 0 fluid, 1 sea, 2 ship
  std::unique_ptr<lbm::Solver> solver_;
  std::unique_ptr<FineRegion> fine_;
  std::vector<std::uint32_t> window_cells_;  // the coarse nodes that feed the fine region
  std::vector<float> window_;                // their air after the last step (m/s)
  std::vector<std::uint8_t> voxelise(double t) const;
  std::vector<float> fine_window();
  void start_fine();  // the fine region from the coarse air now
  void rebuild(double t, bool carry);
  lbm::WallMotion hull_motion(double t) const;
};

// Lattice set-up of a wake domain (for the bench and the tests): units from the config and ship length.
lbm::UnitConverter wake_units(const WakeConfig& cfg, double ship_length);

}  // namespace ship_lrm::wake
