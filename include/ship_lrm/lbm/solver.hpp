// Run-time selectable LBM solver (CPU/OpenMP or CUDA) over a Lattice description.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "ship_lrm/lbm/grid_feed.hpp"
#include "ship_lrm/lbm/lattice.hpp"
#include "ship_lrm/lbm/lattice_view.hpp"

namespace ship_lrm::lbm {

enum class Backend { Cpu, Cuda, Auto };
Backend parse_backend(const std::string& s);  // "cpu", "cuda", "auto"; ConfigError otherwise
const char* to_string(Backend b);
CollisionModel parse_collision_model(const std::string& s);  // "bgk", "recursive"; ConfigError otherwise
const char* to_string(CollisionModel m);
bool cuda_available();  // compiled with CUDA and a device is present

// Raised by the divergence guard: names the step, the first offending cell and the density and speed
// the guard found there (lattice units; the guard wants a density > 0 and a speed up to `limit`).
class DivergenceError : public std::runtime_error {
 public:
  DivergenceError(long step, int x, int y, int z, float density, float speed, float limit);
  long step;
  int x, y, z;
};

// The first cell of a set-up state (rho, u in lattice units; either may be empty) that Solver::initialize
// refuses: density outside (0, 2), or speed not finite or above kMaxSetupMach c_s; -1 when none.
long first_invalid_setup_cell(const std::vector<float>& rho, const std::vector<float>& u, float* speed = nullptr);
float max_setup_speed();  // kMaxSetupMach c_s, lattice units

// Motion of a lattice's frame (see Solver::set_frame_motion), lattice units.
struct FrameMotion {
  std::array<float, 3> acceleration{0, 0, 0};  // of the reference point, frame axes
  std::array<float, 3> omega{0, 0, 0};         // angular velocity, frame axes
  std::array<float, 3> omega_dot{0, 0, 0};     // its rate of change
  std::array<float, 3> centre{0, 0, 0};        // reference point, cell coordinates
};
// The fictitious-force coefficients of a frame motion (Landau & Lifshitz eq. 39.7, see FrameForce).
FrameForce frame_force(const FrameMotion& m);

// Macroscopic fields, one value (rho) or three (u, interleaved x y z) per cell, x fastest.
struct Fields {
  std::vector<float> rho;
  std::vector<float> u;
};

class Solver {
 public:
  virtual ~Solver() = default;
  Solver(const Solver&) = delete;
  Solver& operator=(const Solver&) = delete;

  virtual const char* backend_name() const = 0;
  const Lattice& lattice() const { return lattice_; }
  long steps_done() const { return steps_; }

  // Initialise every fluid cell at equilibrium with the given density and velocity (per cell,
  // sizes cells() and 3*cells(); empty vectors mean rho = 1, u = 0).
  void initialize(const std::vector<float>& rho, const std::vector<float>& u);
  // Advance n time steps. Throws DivergenceError if the guard trips.
  void step(long n = 1);
  // Density and velocity of every cell (walls: rho = 1, u = 0).
  Fields fields();
  // Force density field (3 per cell, interleaved; empty clears it), added to the uniform force.
  virtual void set_force_field(const std::vector<float>& f) = 0;
  void set_uniform_force(const std::array<float, 3>& f);
  // Motion of the lattice's frame relative to an inertial one (lattice units: cells, steps; centre in
  // cell coordinates): the fictitious forces of add_frame_force act on every fluid cell from now on.
  // A frame at rest (all zero) switches them off.
  void set_frame_motion(const FrameMotion& m);
  // New rigid-body motion of moving wall `wall` (an index from Lattice::add_wall_motion).
  void set_wall_motion(int wall, const WallMotion& m);
  // Velocity (3 per listed cell, interleaved) of some cells; only those are read (and, on a GPU, copied).
  std::vector<float> velocities(const std::vector<std::uint32_t>& cells);
  // Change the force density of some cells (3 values per listed cell), others keep theirs; the
  // first call sets up a zero force field. Only the listed cells are written (and copied to a GPU).
  void set_cell_forces(const std::vector<std::uint32_t>& cells, const std::vector<float>& f);
  // Forces of listed cells as a sum of per-cell columns (column_series.hpp; the LRM's rotor disk, whose
  // columns are the harmonics' azimuth functions): the cells and their columns (basis[m * cells.size()
  // + k], 1 <= columns <= kMaxForceColumns) once, then the columns' coefficients (3 per column) whenever
  // the forces change. The backend sums where the lattice lives, so on a GPU only the coefficients
  // cross the bus (a kernel argument). The cells' forces are then as set_cell_forces would set them.
  void set_cell_force_columns(const std::vector<std::uint32_t>& cells, const std::vector<float>& basis, int columns);
  void set_cell_force_coefficients(const std::vector<float>& coefficients);
  // Values of the open-boundary cells, 4 per cell in lattice().boundary_cells() order:
  // velocity inlet (ux, uy, uz, -), pressure outlet (rho, -, -, -), impedance outlet (the undisturbed
  // flow's velocity ux, uy, uz there, -). An impedance outlet admits only outgoing waves relative to
  // that reference: when it changes (a moving or accelerating domain, a new stream), the outlet's
  // normal velocity follows the change in the next step without a density jump (see
  // impedance_density). The 4th value is the solver's own.
  void set_boundary_values(const std::vector<float>& values);
  // The values as the solver holds them (copied back from a GPU when a device feed wrote them).
  const std::vector<float>& boundary_values();
  // Whether this backend computes the velocity faces from a gridded field itself (feed_from_grid).
  virtual bool feeds_from_grid() const { return false; }
  // The velocity inlets and impedance outlets take the field of grid_feed.hpp (two frames of a window,
  // placed and moving as `feed` says) as computed by the backend where the faces live (the CUDA
  // backend: one kernel; only the feed's parameters, and a window when it changed, cross the bus).
  // Windows are copied when their `serial` differs from the last copied one (0: always). Pressure
  // outlets keep their values. The Mach limit (kMaxSetupMach c_s) is checked when the values are
  // next needed on the host: the next feed, set_boundary_values or boundary_values() throws
  // ConfigError if a fed face exceeded it. ConfigError on a backend without it (feeds_from_grid()).
  void feed_from_grid(const GridWindowView& w0, std::uint64_t serial0, const GridWindowView& w1, std::uint64_t serial1,
                      const GridFeed& feed);
  // The same faces on any backend: feed_from_grid where the backend feeds its faces itself, else on
  // the host with the same per-cell function (feed_boundary_cell, OpenMP), checked there: a face
  // beyond the Mach limit throws ConfigError with nothing changed.
  void feed_faces_from_grid(const GridWindowView& w0, std::uint64_t serial0, const GridWindowView& w1, std::uint64_t serial1,
                            const GridFeed& feed);
  // Check the guard now (NaN / speed above mach_guard * c_s); throws DivergenceError.
  void check_divergence();
  // Raw populations (shifted, g = f - w) for tests: Q * cells, SoA.
  virtual std::vector<float> populations() = 0;
  // Put back populations from populations() taken after `steps` steps (a checkpoint): the stored
  // layout depends on the step parity, so the step count comes back with them. Impedance outlets
  // restart from their reference flow. Throws ConfigError for a wrong size or non-finite values.
  void restore(long steps, const std::vector<float>& g);
  // The open boundaries' memory between steps, for an exact checkpoint of a lattice with open faces:
  // every cell's stored state (4 per cell: the last step's rho, u of the boundary and support cells;
  // empty without open boundaries) and the boundary values (4 per boundary cell). Given back after
  // restore() (same lattice), the next step is the one the uninterrupted run takes, bit for bit.
  struct OpenBoundaryState {
    std::vector<float> cell_state, values;
  };
  OpenBoundaryState open_boundary_state();
  void restore_open_boundary_state(const OpenBoundaryState& s);  // ConfigError for wrong sizes or non-finite values
  // New wall cells without a restart (a moving body re-voxelised): `next` describes this lattice
  // (same size, faces, collision, number of wall motions and open-boundary cells) with other wall
  // cells; the open-boundary cells' links and gradient stencils may change with them. Fluid cells that stay fluid keep their
  // populations, non-equilibrium part included; from the next step on, links to cells that became
  // walls bounce back and links to cells that left a wall stream. A cell that left a wall starts at
  // equilibrium with the state refill_states gives it (refill.hpp); force densities, wall motions
  // (next's), boundary values and the step count stay. On success `next` is taken (moved from) and
  // true returned; false, with nothing changed and `next` kept (finalized), when it differs in more
  // than its walls or the backend cannot (in_place_walls()): then make a new solver on it, carrying
  // the flow over with carry_flow. Solver construction, the start state and every non-wall cell's
  // history are what a rebuild costs and loses (about 10 ms and the stresses at 40^3 on 2 cores).
  // restart_flow: then every cell restarts at equilibrium with its density and velocity (the cells
  // that left a wall with the refill's), and the step count at 0: what a new solver started with
  // carry_flow's fields would do, without making one (see LrmDomain::rebuild).
  bool change_walls(Lattice& next, bool restart_flow = false);
  virtual bool in_place_walls() const { return false; }
  // Wait for queued device work (timing); no-op on the CPU.
  virtual void synchronize() {}

 protected:
  explicit Solver(Lattice lattice);
  // initialize() without its check of the state (change_walls has checked it)
  void start_from(const std::vector<float>& rho, const std::vector<float>& u);
  // Backend work: one step of the given parity (the held cells' hold_cell after it included), field
  // extraction and equilibrium initialisation.
  virtual void do_step(bool odd) = 0;
  virtual void do_fields(bool next_odd, Fields& out) = 0;
  virtual void do_initialize(const std::vector<float>& rho, const std::vector<float>& u) = 0;
  virtual void do_set_populations(const std::vector<float>& g) = 0;           // validated, populations() layout
  virtual std::vector<float> do_cell_state() = 0;                             // the aux array, 4 per cell (empty: none)
  virtual void do_set_cell_state(const std::vector<float>& a) = 0;            // validated, do_cell_state() layout
  virtual void sync_view() = 0;                                               // after view_ parameters changed on the host
  virtual void sync_walls() {}                                                // after lattice_'s wall motions changed (device copy)
  virtual void do_set_boundary_values(const std::vector<float>& values) = 0;  // validated, 4 per cell
  // Device-side faces (feeds_from_grid backends): compute them; the largest face speed of the last
  // feed (lattice units; waits for it); copy the values into boundary_values_. do_clear_reference_change:
  // after the host copy's impedance 4th values were zeroed, the same where the values live (default:
  // upload the host copy).
  virtual void do_feed_from_grid(const GridWindowView&, std::uint64_t, const GridWindowView&, std::uint64_t, const GridFeed&) {}
  virtual float do_fed_speed() { return 0.0f; }
  virtual void do_pull_boundary_values() {}
  virtual void do_clear_reference_change();
  // Listed cells only (validated): velocities out, force densities in; no whole-field traffic.
  virtual void do_velocities(bool next_odd, const std::vector<std::uint32_t>& cells, std::vector<float>& out) = 0;
  virtual void do_set_cell_forces(const std::vector<std::uint32_t>& cells, const std::vector<float>& f) = 0;
  // The force columns (validated; default: kept here) and their sum with new coefficients (validated;
  // default: column_series on the host, then do_set_cell_forces).
  virtual void do_set_cell_force_columns(const std::vector<std::uint32_t>& cells, const std::vector<float>& basis, int columns);
  virtual void do_set_cell_force_coefficients(const std::vector<float>& coefficients);
  // change_walls, after the checks: the state (rho, u) of a fluid cell between steps, and adopting
  // `next` with the listed cells (those that left a wall) started at equilibrium with `states`.
  virtual Macro do_cell_state(bool next_odd, std::size_t c);
  virtual void do_change_walls(Lattice&& next, const std::vector<std::uint32_t>& freed, const std::vector<std::array<float, 4>>& states);
  // Index of the first cell whose speed is non-finite or above limit, or -1.
  virtual long long do_find_divergent(bool next_odd, float limit) = 0;

  Lattice lattice_;
  int force_columns_ = 0;                                          // set_cell_force_columns' column count (0: none)
  std::vector<std::uint32_t> column_cells_;                        // its cells (default do_set_cell_force_columns)
  std::vector<float> column_basis_, column_sums_, column_forces_;  // its columns; scratch of the host's sum
  std::vector<float> boundary_values_;                             // host copy; 4th value of impedance cells: reference change
  bool reference_change_pending_ = false;
  bool boundary_values_on_device_ = false;  // a device feed wrote them; boundary_values_ is stale
  bool feed_unchecked_ = false;             // the last device feed's Mach limit not yet checked
  void clear_reference_change();
  void check_fed_speed();       // ConfigError when the last device feed exceeded the Mach limit
  void pull_boundary_values();  // boundary_values_ up to date (and checked)
  LatticeView view_;            // host copy of the view; device pointers in the CUDA backend
  long steps_ = 0;
};

std::unique_ptr<Solver> make_solver(Lattice lattice, Backend backend);
std::unique_ptr<Solver> make_cpu_solver(Lattice lattice);
std::unique_ptr<Solver> make_cuda_solver(Lattice lattice);  // ConfigError without CUDA

}  // namespace ship_lrm::lbm
