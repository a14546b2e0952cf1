// Host-side description of a lattice: size, collision parameters, face and per-cell boundary
// conditions. It validates the set-up (clear exceptions for bad input) and derives the cell lists
// that the backends iterate over.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "ship_lrm/common/config_error.hpp"
#include "ship_lrm/lbm/cell_ops.hpp"
#include "ship_lrm/lbm/cell_types.hpp"

namespace ship_lrm::lbm {

struct FaceCondition {
  FaceType type = FaceType::Wall;
  std::array<float, 3> velocity{0, 0, 0};  // MovingWall / VelocityInlet (lattice units)
  float density = 1.0f;                    // PressureOutlet
  // ImpedanceOutlet: where the flow enters, take the tangential velocity from the reference flow
  // given with Solver::set_boundary_values (a domain inside a known outer flow, the LRM) instead of
  // extrapolating it from the interior.
  bool inflow_from_reference = false;
  // ImpedanceOutlet: fraction K (per step, in [0, 1)) by which the outlet's density returns to the
  // reference density 1 each step. 0 is the thesis' outlet (eq. 6.15): it admits only outgoing waves,
  // but it has no reference pressure, so a steady state keeps whatever p' = rho c_s u_n' its history
  // left (with u_n' the normal velocity's departure from the reference flow): for the slow, steady
  // disturbance of a lifting rotor the face is nearly closed at a low lattice Mach number. K > 0 is
  // the partially non-reflecting outlet of Rudy & Strikwerda (1980, J. Comput. Phys. 36, 55) and
  // Poinsot & Lele (1992, J. Comput. Phys. 101, 104: K = sigma (1 - M^2) c / L): waves much
  // faster than K still leave, and the steady pressure at the face is the reference's.
  float pressure_relaxation = 0.0f;
  // PressureOutlet: an entraining face in still air. Where the air leaves, the face holds `density`
  // (the ambient pressure); where it enters, the air has come from rest in the ambient, so by
  // Bernoulli its static pressure is lower by the dynamic pressure of its inward normal velocity u_in:
  // rho = density (1 - u_in^2 / (2 c_s^2)), u_in from the cell's previous step (the total-pressure
  // inlet-outlet condition of free-jet and entrainment flows, e.g. OpenFOAM's totalPressure with
  // pressureInletOutletVelocity). Unlike a fixed pressure on every face it pins the frame: a uniform
  // drift through the domain would enter below the pressure at which it leaves, so it decays.
  bool total_pressure_inflow = false;
  // VelocityInlet: a characteristic (non-reflecting) inlet. The velocity prescribes the wave that
  // enters; the acoustic wave that leaves through the face passes, its outward normal velocity
  // c_s (rho - 1) / rho added to the prescribed one (p' = rho c_s u' for a wave moving outward;
  // Thompson 1987, J. Comput. Phys. 68, 1; for LBM Izquierdo & Fueyo 2008, Phys. Rev. E 78, 046707).
  // The plain inlet reflects that wave, and with an outlet opposite it a disturbed stream grows
  // (`validate stream-stability --faces inlet-outlet`). The mean inflow then follows the pressure at
  // the face: lower by c_s (rho - 1) where the flow raises it.
  bool characteristic_inlet = false;
  // VelocityInlet: an absorbing layer of this many cells inside the face (0: none). After each step
  // the velocity of each fluid cell at d = 1 .. absorbing_cells cells from the face moves towards the
  // prescribed velocity of the face cell in its row (the same coordinates along the face):
  //   u <- u + sigma(d) (u_face - u),  sigma(d) = absorbing_strength ((L + 1 - d) / (L + 1))^2,
  // through the equilibrium part of its populations (lattice_view.hpp, absorb_cell). A sponge in the
  // sense of Israeli & Orszag (1981, J. Comput. Phys. 41, 115; for LBM Xu & Sagaut 2013, J. Comput.
  // Phys. 245, 14) that relaxes the velocity towards the inflow rather than raising the viscosity, so
  // the air the face feeds in is the target, not damped towards a mean. It removes the grid-scale
  // mode where the inlet meets a moving ground (docs/design.md, "The ground corner's mode"). Cost: the layer's
  // cells only, in a pass after the step (like the held cells').
  int absorbing_cells = 0;
  float absorbing_strength = 0.0f;  // per step, in (0, 1]
};

struct LatticeConfig {
  int nx = 0, ny = 0, nz = 0;
  CollisionParams collision;
  std::array<FaceCondition, 6> faces;  // -x, +x, -y, +y, -z, +z
  std::array<float, 3> uniform_force{0, 0, 0};
  // Divergence guard: stop when a cell's speed exceeds mach_guard * c_s or is not finite.
  float mach_guard = 1.0f;
  int guard_interval = 64;  // steps between guard checks (0: off)
};

// Largest lattice Mach number u/c_s accepted for a set-up's reference velocity. The thesis runs at
// u_ref = 0.3 c_s (tables 6.2-6.4); compressibility errors grow with Ma^2.
constexpr float kMaxSetupMach = 0.4f;

// A contiguous run of fluid cells along x with the same cell class (neighbour offsets, see
// cell_class in lattice_view.hpp), link mask (which neighbours are resting walls or outside) and
// reflection rule: the CPU backend streams a segment with one table of addresses, vectorised.
// store_state: cells of the open boundaries' support set are among them, so their update also
// stores their pre-collision state (aux) for the boundary passes (all of the run's cells do: a row
// stays one long vectorised run instead of splitting into short ones at the support set's edge; the
// boundary passes read aux of support cells only).
struct Segment {
  std::uint32_t first;
  std::uint32_t count;
  std::uint32_t cell_class;
  std::uint32_t link_mask;
  std::uint8_t reflection;
  std::uint8_t store_state;
};

class Lattice {
 public:
  explicit Lattice(const LatticeConfig& cfg);

  const LatticeConfig& config() const { return cfg_; }
  int nx() const { return cfg_.nx; }
  int ny() const { return cfg_.ny; }
  int nz() const { return cfg_.nz; }
  std::size_t cells() const { return static_cast<std::size_t>(cfg_.nx) * cfg_.ny * cfg_.nz; }
  std::size_t index(int x, int y, int z) const {
    return static_cast<std::size_t>(x) +
           static_cast<std::size_t>(cfg_.nx) * (static_cast<std::size_t>(y) + static_cast<std::size_t>(cfg_.ny) * z);
  }

  // Per-cell conditions (before the solver is made).
  void set_wall(int x, int y, int z);
  // Slip wall cell. Fluid cells that touch slip walls across one plane only (all and only their
  // links with one sign along one axis hit slip walls) reflect specularly; elsewhere (edges,
  // corners, mixed with no-slip walls) bounce-back applies, so mass is conserved everywhere.
  void set_slip_wall(int x, int y, int z);
  // Moving no-slip wall cell that belongs to rigid body `wall` (see add_wall_motion).
  void set_moving_wall(int x, int y, int z, int wall);
  int add_wall_motion(const WallMotion& m);
  // Change the motion of a wall (also after finalize(); Solver::set_wall_motion passes it on).
  void set_wall_motion(int wall, const WallMotion& m);
  // Open boundary cells; only on a non-periodic face of the domain.
  void set_velocity_inlet(int x, int y, int z, const std::array<float, 3>& u);
  void set_pressure_outlet(int x, int y, int z, float rho);
  void set_impedance_outlet(int x, int y, int z);
  // Held fluid cell: fluid inside a solid body where no wall may stand (the LRM keeps walls out of
  // its two outermost layers, thesis 6.4). After every step the populations it emitted are replaced
  // by the equilibrium with their mass and the velocity of rigid body `wall` (add_wall_motion) at its
  // centre, or at rest for kHeldAtRest (hold_cell): the air inside the body moves with it, not a free layer
  // between the body and the faces (that layer grew a jet until the flow diverged). Only plain fluid
  // cells (not walls or open-boundary cells; finalize() checks), each at most once.
  static constexpr int kHeldAtRest = -1;
  void set_held(int x, int y, int z, int wall);

  CellType type(int x, int y, int z) const { return static_cast<CellType>(type_[index(x, y, z)]); }

  // Derived lists (valid after finalize(), which the solver calls).
  void finalize();
  bool finalized() const { return finalized_; }
  const std::vector<std::uint8_t>& types() const { return type_; }  // with kGeneralBit
  const std::vector<std::uint8_t>& tags() const { return tag_; }
  const std::vector<WallMotion>& wall_motions() const { return walls_; }
  const std::vector<Segment>& bulk_segments() const { return segments_; }
  // Fluid cells next to moving walls (checked streaming path on the CPU).
  const std::vector<std::uint32_t>& general_cells() const { return general_; }
  // Link masks (see gather_masked in lattice_view.hpp) of the general and boundary cells.
  const std::vector<std::uint32_t>& general_link_masks() const { return general_mask_; }
  // Neighbour offsets of bulk cells, Q per cell class (see cell_class in lattice_view.hpp).
  const std::vector<std::int64_t>& row_offsets() const { return row_offsets_; }
  const std::vector<std::uint32_t>& boundary_cells() const { return bnd_cell_; }
  const std::vector<std::uint8_t>& boundary_normals() const { return bnd_normal_; }
  const std::vector<float>& boundary_values() const { return bnd_value_; }  // 4 per boundary cell
  const std::vector<std::uint32_t>& boundary_link_masks() const { return bnd_mask_; }
  // Velocity-gradient stencils of the boundary cells, 9 cells and 9 weights each (gradient_stencil).
  const std::vector<std::uint32_t>& boundary_gradient_cells() const { return bnd_grad_cell_; }
  const std::vector<float>& boundary_gradient_weights() const { return bnd_grad_weight_; }
  // Held cells in cell order and the wall index of each (kHeldWallAtRest for kHeldAtRest).
  const std::vector<std::uint32_t>& held_cells() const { return held_cell_; }
  const std::vector<std::uint8_t>& held_walls() const { return held_wall_; }
  // The absorbing layers' cells (FaceCondition::absorbing_cells): plain fluid cells, not held, at
  // d = 1 .. absorbing_cells from such a face whose face cell in the same row is a velocity inlet;
  // per cell that boundary index and sigma(d) (of the nearest such face where layers overlap).
  const std::vector<std::uint32_t>& absorbing_cells() const { return absorbing_cell_; }
  const std::vector<std::uint32_t>& absorbing_targets() const { return absorbing_target_; }
  const std::vector<float>& absorbing_sigmas() const { return absorbing_sigma_; }

 private:
  void check_cell(int x, int y, int z, const char* what) const;
  std::uint8_t reflection_mode(int x, int y, int z) const;
  std::uint32_t link_mask(int x, int y, int z, const std::array<std::uint32_t, 27>& face_links) const;
  void set_open(int x, int y, int z, CellType t, const std::array<float, 4>& value);
  int open_normal(int x, int y, int z) const;  // outward normal code, or -1 if not on an open-able face
  std::vector<char> support_marks() const;
  void order_held_cells();  // in cell order, each checked (finalize)

  LatticeConfig cfg_;
  std::vector<std::uint8_t> type_, tag_;
  std::vector<std::pair<std::uint32_t, std::array<float, 4>>> explicit_values_;  // per-cell open values
  std::vector<WallMotion> walls_;
  bool finalized_ = false;
  std::vector<Segment> segments_;
  std::vector<std::uint32_t> general_, general_mask_, bnd_cell_, bnd_mask_, bnd_grad_cell_;
  std::vector<std::uint8_t> bnd_normal_;
  std::vector<std::uint32_t> held_cell_;
  std::vector<std::uint8_t> held_wall_;
  std::vector<std::int64_t> row_offsets_;
  std::vector<float> bnd_value_, bnd_grad_weight_;
  std::vector<std::uint32_t> absorbing_cell_, absorbing_target_;
  std::vector<float> absorbing_sigma_;
};

}  // namespace ship_lrm::lbm
