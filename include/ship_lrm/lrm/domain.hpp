// The LRM fluid domain (thesis 5.2, 6.4, 6.5): a lattice-Boltzmann cube of edge a * 4R with N nodes
// per 4R, the rotor disk at its centre, axes parallel to the rotor's mr frame (x forward, y
// starboard, z down). Faces (configurable): velocity front (+x), left (-y), right (+y), fed with the
// air velocity relative to the domain; impedance back (-x), top (-z), bottom (+z). The rotor's
// aerodynamic force (on the blades) is imposed with the opposite sign on the fluid in the disk's
// cell layer; the inflow is read back as mean + linear harmonics (rotor/disk_coupling.hpp), in m/s
// relative to the domain: the rotor-inflow interface of inflow_model.hpp.
//
// Domain motion (docs/design.md, "The domain moves with the rotorcraft"): the grid stays fixed to the rotorcraft, so
// it translates and rotates with it. The faces get the air velocity relative to the moving grid,
// air - omega x r, and every cell gets the frame's fictitious forces (lbm::add_frame_force). The
// thesis' alternative was an ALE domain that interpolates the populations each step. That is
// diffusive, and the thesis neglects rotation. Here a domain moving at constant velocity is exactly
// the fixed domain with the stream at its faces (Galilean invariance), and rotation costs 15 numbers
// per step.
#pragma once

#include <array>
#include <limits>
#include <memory>
#include <optional>
#include <string>

#include "ship_lrm/common/vec.hpp"
#include "ship_lrm/lbm/solver.hpp"
#include "ship_lrm/lbm/units.hpp"
#include "ship_lrm/lrm/walls.hpp"
#include "ship_lrm/rotor/disk_coupling.hpp"
#include "ship_lrm/rotor/inflow_model.hpp"

namespace ship_lrm::lrm {

// A wall (wall() names it: "ground", "ship", ...) has reached cells of the rotor disk, where the LRM
// cannot place it (the disk's forces act on fluid cells). At the start that is bad input; in free
// flight it is a rotor strike, which ends the flight (ShipApproach).
class WallOnRotorDisk : public ConfigError {
 public:
  explicit WallOnRotorDisk(const std::string& wall)
      : ConfigError("LRM: the " + wall + " covers part of the rotor disk; move the rotor clear of it"), wall_(wall) {}
  const std::string& wall() const { return wall_; }

 private:
  std::string wall_;
};

struct LrmConfig {
  int nodes = 64;                                            // N: lattice nodes across 4R (thesis 6.4)
  double reach = 1.25;                                       // a >= 1: domain edge / 4R
  double radius = 4.92;                                      // m (thesis' LRM tables)
  double density = 1.1934;                                   // kg/m^3 (thesis table 6.4)
  double viscosity = 1.46072e-4;                             // m^2/s (thesis table 6.4)
  double reference_velocity = 30.0;                          // m/s mapped to 0.3 c_s (thesis table 6.4)
  double smagorinsky = 0.05;                                 // thesis 6.1 (LRM domain)
  lbm::CollisionModel collision = lbm::CollisionModel::Bgk;  // lbm/cell_ops.hpp
  // Velocity faces as characteristic inlets (lbm::FaceCondition::characteristic_inlet)
  bool characteristic_inlets = false;
  // Velocity faces with an absorbing layer of this many cells (lbm::FaceCondition::absorbing_cells;
  // 0: none) and strength (per step at the face): it pulls the air next to the face towards the face's
  // air, which damps the grid-scale mode where the inflow face meets a moving ground.
  int absorbing_layer = 0;
  double absorbing_strength = 0.5;
  lbm::Backend backend = lbm::Backend::Auto;
  // Impedance faces: sigma of the partially non-reflecting outlet (lbm::FaceCondition::pressure_relaxation,
  // K = sigma (1 - Ma^2) c_s / L per step with L the domain edge in cells, Poinsot & Lele 1992); 0: the
  // thesis' outlet without a reference pressure. Per face, in the order of `faces`.
  std::array<double, 6> outlet_sigma = {0, 0, 0, 0, 0, 0};
  // The faces' undisturbed air includes the rotor's own far field: the induced velocity of a uniformly
  // loaded disk with the rotor's mean thrust (rotor/vortex_cylinder.hpp) at each face cell, added to
  // the velocity faces' values and to the impedance faces' reference. A finite domain's faces
  // otherwise act on the rotor like the walls of a wind tunnel (docs/design.md, "Face interference").
  // Updated when the thrust changes by more than 2 % or the air by more than 2 % of its speed: rescaled
  // with the wake's circulation while the wake keeps its direction (within 1 deg), computed anew
  // otherwise (the rings' multipole sums: 0.1 s at N = 32, 0.4 s at N = 64 on 2 cores); the faces
  // are then fed on the host. The air it is computed for: that of set_motion, or with a face grid (a
  // ship's wake, set_face_grid) the grid's air at the disk's centre averaged over the last second.
  bool rotor_far_field = false;
  // Pressure-outlet faces entrain (lbm::FaceCondition::total_pressure_inflow): air leaving holds the
  // ambient pressure, air entering comes from rest in the ambient (Bernoulli).
  bool entraining_pressure_faces = false;
  // -x (back), +x (front), -y (left), +y (right), -z (top), +z (bottom)
  std::array<lbm::FaceType, 6> faces = {lbm::FaceType::ImpedanceOutlet, lbm::FaceType::VelocityInlet,   lbm::FaceType::VelocityInlet,
                                        lbm::FaceType::VelocityInlet,   lbm::FaceType::ImpedanceOutlet, lbm::FaceType::ImpedanceOutlet};
};

// cfg with the lattice reference velocity (0.3 c_s) standing for the fastest stream when that exceeds
// cfg.reference_velocity (thesis: 30 m/s), so the lattice Mach number stays 0.3; the time step shrinks.
LrmConfig config_for_stream(LrmConfig cfg, double fastest_stream);

// The lattice units of cfg's domain (dx, dt, ...) without building it; ConfigError as LrmDomain.
lbm::UnitConverter lattice_units(const LrmConfig& cfg);

class LrmDomain {
 public:
  // Throws ConfigError for a < 1, N < 16 or a set-up beyond the Mach limit.
  explicit LrmDomain(const LrmConfig& cfg);

  const LrmConfig& config() const { return cfg_; }
  const lbm::UnitConverter& units() const { return units_; }
  int cells_per_edge() const { return edge_; }
  double centre() const { return centre_; }         // cell coordinate of the hub on each axis
  double time_step() const { return units_.dt(); }  // s, one LBM step
  double time() const { return steps_ * units_.dt(); }
  // Moves the domain's clock on by n LBM steps without stepping the flow (a real-time run that has
  // fallen behind drops its backlog: LrmInflow::set_catch_up_limit). The flow is kept as it is.
  void skip_steps(long n) {
    if (n > 0) steps_ += n;
  }
  const rotor::DiskCoupling& disk() const { return disk_; }
  lbm::Solver& solver() { return *solver_; }

  // Motion of the domain relative to the undisturbed air (uniform, at rest or in steady wind).
  struct Motion {
    Vec3 air_velocity = Vec3::Zero();      // air relative to the hub, mr axes, m/s (= -hub velocity in still air)
    Vec3 omega = Vec3::Zero();             // angular velocity of the mr frame, mr axes, rad/s
    Vec3 omega_dot = Vec3::Zero();         // its rate of change, rad/s^2
    Vec3 hub_acceleration = Vec3::Zero();  // inertial acceleration of the hub, mr axes, m/s^2
  };
  // The velocity faces get air_velocity - omega x r (r from the hub), every cell the fictitious
  // forces. Throws ConfigError when a face velocity exceeds the lattice Mach limit.
  void set_motion(const Motion& m);
  // A domain translating at constant velocity: set_motion with air_velocity only.
  void set_stream(const Vec3& air_velocity);
  const Motion& motion() const { return motion_; }
  // The undisturbed air is not uniform (a ship wake): the faces take a gridded field (two frames of a
  // window, wake::WakeTable::frames; lbm/grid_feed.hpp) seen from a hub at `hub` (m, grid frame) with
  // axes `rotation` (mr -> grid) moving at `hub_velocity` (m/s, grid frame). Each face cell gets the
  // field's air relative to the hub at its place, in mr axes, which replaces motion().air_velocity
  // (minus omega x r as before) until clear_face_grid(). The domain keeps its own copy of the windows
  // (copied again only when a serial changes), so walls that move through a face keep the field.
  // Where the solver feeds its faces itself (CUDA), the field is interpolated on the device and the
  // Mach limit is checked at the next feed (lbm::Solver::feed_from_grid); otherwise here, before
  // anything changes. ConfigError for a non-finite pose or a face velocity beyond the Mach limit (the
  // faces then stay as they were).
  void set_face_grid(const lbm::GridWindowView (&window)[2], const std::uint64_t (&serial)[2], const lbm::GridFeed& grid, const Vec3& hub,
                     const Mat3& rotation, const Vec3& hub_velocity);
  void clear_face_grid();
  bool has_face_grid() const { return grid_.has_value(); }
  // The undisturbed air at r (m from the hub, mr axes) relative to the grid, as the velocity faces take
  // it without the rotor's far field: the face grid's field (a ship's wake), else the motion's uniform
  // air, minus omega x r either way (m/s, mr axes). For comparing the flow inside with what feeds the
  // faces (the approach's centre plane beside the table's, thesis fig. 9.3 (c)).
  Vec3 undisturbed_air(const Vec3& r) const;
  // Position of a cell centre relative to the hub (m, mr axes).
  Vec3 position(int i, int j, int k) const;
  Vec3 position(std::size_t cell) const;  // the same for a lattice index (x fastest)
  // Restart the flow: every cell at rest density with the undisturbed air at its place (the face
  // grid's, a ship's wake, else the current motion's uniform air), so that the outlets start in step
  // with the air they are given as reference.
  // An impulsive start from rest instead sends a compression wave through the domain that the
  // non-reflecting outlets let out without restoring the density (no reference pressure).
  void restart_flow();
  // Solid bodies (walls.hpp): the ground, a ship deck, the fuselage. Adding one, or update_walls()
  // after one moved, re-voxelises the domain: cells whose centre lies inside become no-slip walls
  // (halfway bounce-back), moving with the body (Ladd's moving-wall term), or slip walls for a body
  // that asks for them (WallSurface::slip: a level ground sliding along itself). The solid continues
  // through the outer layers to the faces, except for bodies that are kept clear of the faces
  // (WallSurface::clear_of_faces: the ship and the sea, thesis 6.4): in their two outermost layers
  // the cells inside such a body (the face cells excepted) are held cells (lbm::Lattice::set_held),
  // fluid that moves with the body, instead of free fluid in a dead end between the body and the
  // faces, which grew a jet until the flow diverged (design.md, "Walls that move").
  // When the set of wall cells changed, the solver takes the new walls in place where it
  // can (lbm::Solver::change_walls, the CPU): the fluid cells keep their populations. Otherwise (the
  // CUDA backend, or a wall that crossed a face) a new solver starts from the flow at equilibrium
  // with each cell's density and velocity. Either way, cells that left a body are refilled with the
  // mean state of their fluid neighbours, the usual refill of moving-boundary LBM (e.g. Lallemand &
  // Luo 2003, J. Comput. Phys. 184, 406). Throws ConfigError when a body covers a rotor-disk
  // cell; the domain then stays as it was.
  void add_wall(std::shared_ptr<WallSurface> wall);
  void update_walls();
  // Walls whose velocity changed but not (visibly) their place: the new motions go to the solver
  // without re-voxelising (a wall that starts or stops moving re-voxelises).
  void update_wall_motions();
  std::size_t wall_cells() const { return wall_cells_; }
  std::size_t rebuilds() const { return rebuilds_; }            // changes of the wall cells after the first (moving walls)
  std::size_t face_restarts() const { return face_restarts_; }  // of those, the ones next to the faces (the flow restarted)
  double wall_seconds() const { return wall_seconds_; }         // wall-clock time in update_walls (voxelising and changing)
  // LrmConfig::rotor_far_field: the rotor's induced velocity at each boundary cell (m/s, mr axes, the
  // solver's boundary_cells() order; empty before the first set_rotor_forces with thrust), how often
  // it changed (a change of thrust or airspeed by more than 2 %) and how often its shape was computed
  // for that (a change that leaves the wake's direction within 1 deg only rescales it).
  const std::vector<Vec3>& far_field() const { return far_field_; }
  std::size_t far_field_updates() const { return far_field_updates_; }
  std::size_t far_field_builds() const { return far_field_builds_; }
  double far_field_seconds() const { return far_field_seconds_; }  // wall-clock time spent computing its shape
  // LrmConfig::rotor_far_field over flat ground parallel to the disk, `height` m below the hub (where
  // the bounce-back wall lies, half-way between the last fluid and the first wall cell): the far field
  // gets the ground's mirror image (rotor::VortexCylinderWake::set_ground), so that the faces let the
  // air that the ground turns outwards leave instead of holding it in. infinity: no ground (the
  // default). Takes effect at the next set_rotor_forces. Throws ConfigError for a plane that does
  // not lie below the disk.
  void set_far_field_ground(double height);
  // Aerodynamic force on the blades over azimuth (N, mr axes); the fluid gets the opposite.
  void set_rotor_forces(const rotor::RotorForceHarmonics& h);
  // Advance by whole LBM steps (at least one).
  void step(long n = 1);
  // Inflow over the disk (m/s, mr axes, relative to the domain).
  rotor::RotorInflow inflow();

 private:
  LrmConfig cfg_;
  lbm::UnitConverter units_;
  int edge_;
  double centre_;
  rotor::DiskCoupling disk_;
  int disk_layer_;
  std::vector<std::uint32_t> disk_cells_;  // lattice indices of the disk cells, disk_.cells() order
  std::unique_ptr<lbm::Solver> solver_;
  long steps_ = 0;
  Motion motion_;
  // The gridded field the faces take (set_face_grid), with its windows shared between successive
  // feeds that reuse a window.
  struct FaceGrid {
    lbm::GridFeed feed;
    lbm::GridWindowView window[2];
    std::shared_ptr<const std::vector<float>> data[2];
    std::uint64_t serial[2] = {0, 0};
  };
  std::optional<FaceGrid> grid_;
  std::vector<Vec3> face_air_;        // host path: the grid's air per boundary cell (mr axes, m/s)
  std::vector<Vec3> face_positions_;  // position() of each boundary cell of the solver (empty: not listed yet)
  // LrmConfig::rotor_far_field: the rotor's induced velocity per boundary cell (m/s, mr axes), and the
  // thrust and air it was computed for. The field is linear in the wake's circulation, 2 v: it is kept
  // per unit v (far_field_shape_) for the wake direction it was built for, and only rescaled while the
  // direction stays within 1 deg.
  std::vector<Vec3> far_field_, far_field_shape_;
  Vec3 far_field_direction_ = Vec3::Zero();
  std::size_t far_field_builds_ = 0, far_field_updates_ = 0;
  double far_field_seconds_ = 0;
  double far_field_thrust_ = 0, rotor_thrust_ = 0;
  Vec3 far_field_air_ = Vec3::Zero();
  bool far_field_stale_ = true;
  double far_field_ground_ = std::numeric_limits<double>::infinity();  // m below the hub
  // with a face grid: its air at the disk's centre (m/s relative to the hub, mr axes), low-passed over
  // 1 s of the domain's time, for the far field
  Vec3 hub_air_ = Vec3::Zero();
  bool hub_air_set_ = false;
  double hub_air_time_ = 0;
  bool update_far_field(const Vec3& air);  // true when it changed
  bool face_air_stale_ = true;             // the grid or the cell list changed since face_air_ was computed
  bool motion_set_ = false;
  bool faces_hold_air_ = true;  // some face is a velocity or impedance face: it can hold a stream (set once)
  std::vector<std::shared_ptr<WallSurface>> walls_;
  std::vector<std::int16_t> owner_;  // per cell: index of the wall that holds it, or -1
  // per cell of the layers kept clear of walls: index of the body kept clear of the faces it lies in,
  // or -1. The air there moves with that body: fluid cells are held to its motion (Lattice::set_held),
  // face cells take its velocity (body_faces_).
  std::vector<std::int16_t> inside_;
  // open-boundary cells inside such a body (pressure outlets excepted): boundary index and body; their
  // values are the body's velocity (push_face_values), so that the faces and the held cells behind
  // them agree (a velocity face that fed the table's air into held cells that carried the ship's
  // pumped mass into them: density 2.4 at the front face, design.md "Walls that move")
  std::vector<std::pair<std::uint32_t, std::int16_t>> body_faces_;
  std::vector<float> face_values_;  // the faces' values from the air (set_motion's host path), before the bodies'
  bool find_body_faces();           // body_faces_ for the solver's boundary cells; true if they changed
  void push_face_values();          // face_values_ with the bodies' velocities at body_faces_, to the solver
  std::vector<bool> wall_moves_;    // per wall: built as a moving wall
  std::size_t wall_cells_ = 0, rebuilds_ = 0, face_restarts_ = 0;
  double wall_seconds_ = 0;
  // The disk cells' forces as the lattice sums them (Solver::set_cell_force_columns): the columns of
  // DiskCoupling, once per solver, and the last coefficients in lattice units (kept across rebuilds).
  std::vector<float> disk_force_columns_, disk_force_coefficients_;
  // near_faces: wall cells changed within kClearLayers + 1 layers of a face
  void rebuild(bool carry_flow, bool near_faces = false);
  static constexpr int kClearLayers = 2;   // walls that clear_of_faces() stay out of layers 0 .. kClearLayers - 1
  int face_layer(std::size_t cell) const;  // 0 on a face, 1 next to it, ...
  void push_wall_motions();
  lbm::WallMotion lattice_motion(const WallSurface& wall) const;
  // Whether the body is built with moving-wall bounce-back (a no-slip body moving relative to the
  // domain); a slip wall is built at rest, and is refused here if it moves across itself.
  bool builds_as_moving_wall(const WallSurface& wall) const;
};

}  // namespace ship_lrm::lrm
