// Carrying a flow over to a lattice whose walls moved (moving-boundary LBM).
#pragma once
#include "ship_lrm/lbm/lattice.hpp"
#include "ship_lrm/lbm/solver.hpp"

namespace ship_lrm::lbm {

// The density and velocity of `old` (the fields of a solver on lattice `was`) for a lattice of the
// same size whose walls changed. Cells that were walls in `was` are refilled with the mean state of
// their fluid neighbours, front by front, so that a body that moved by several cells at once is filled
// from the fluid inwards: the usual refill of moving-boundary LBM (e.g. Lallemand & Luo 2003,
// J. Comput. Phys. 184, 406). Cells with no fluid anywhere around stay at rest (rho 1, u 0).
Fields carry_flow(const Lattice& was, const Fields& old);

}  // namespace ship_lrm::lbm
