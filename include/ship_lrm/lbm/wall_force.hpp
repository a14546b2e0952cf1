// Force of the fluid on a body of wall cells by momentum exchange (Ladd 1994, J. Fluid Mech.
// 271, 285, eq. 4.1; Krueger et al., The Lattice Boltzmann Method, 2017, section 5.4.2).
#pragma once

#include <array>
#include <vector>

#include "ship_lrm/lbm/solver.hpp"

namespace ship_lrm::lbm {

// body[c] != 0 marks the wall cells of the body. Lattice units (momentum per time step).
// Valid between steps after an even number of steps (throws ConfigError otherwise).
std::array<double, 3> wall_force(Solver& solver, const std::vector<char>& body);

}  // namespace ship_lrm::lbm
