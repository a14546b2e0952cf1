// Carrying a flow over to a lattice whose walls moved (moving-boundary LBM).
#pragma once
#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include "ship_lrm/lbm/lattice.hpp"
#include "ship_lrm/lbm/solver.hpp"

namespace ship_lrm::lbm {

// Density and velocity (rho, ux, uy, uz) for `cells`, cells that were walls in `was` and are fluid
// now: front by front, each takes the mean state of its neighbours that were fluid in `was` or were
// filled in an earlier front, so that a body that moved by several cells at once is filled from the
// fluid inwards: the usual refill of moving-boundary LBM (e.g. Lallemand & Luo 2003, J. Comput.
// Phys. 184, 406). `state(c)` gives the state of a cell that was fluid. Cells that no front reaches
// rest (rho 1, u 0). Returns 4 values per listed cell, in their order.
std::vector<std::array<float, 4>> refill_states(const Lattice& was, const std::vector<std::uint32_t>& cells,
                                                const std::function<std::array<float, 4>(std::size_t)>& state);

// The density and velocity of `old` (the fields of a solver on lattice `was`) for a lattice of the
// same size whose walls changed: the cells that were walls in `was` refilled by refill_states.
Fields carry_flow(const Lattice& was, const Fields& old);

// The same for an in-place restart (Solver::change_walls with restart_flow): only `freed`, the cells
// that leave a wall, are refilled; the others that stay walls keep old's values, which no step reads.
// (carry_flow fills every wall cell, front by front through a thick hull: 0.4 ms at 40^3 with the ship.)
Fields restart_fields(const Lattice& was, Fields old, const std::vector<std::uint32_t>& freed);

}  // namespace ship_lrm::lbm
