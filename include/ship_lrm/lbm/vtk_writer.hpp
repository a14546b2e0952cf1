// VTK XML image data (.vti) of density and velocity for ParaView (appended raw binary).
#pragma once

#include <string>

#include "ship_lrm/lbm/solver.hpp"

namespace ship_lrm::lbm {

// Writes fields of an nx*ny*nz lattice with cell size dx [m] (1 for lattice units) and origin.
// Throws std::runtime_error if the file cannot be written.
void write_vti(const std::string& path, const Lattice& lattice, const Fields& fields, double dx = 1.0, const double origin[3] = nullptr);

}  // namespace ship_lrm::lbm
