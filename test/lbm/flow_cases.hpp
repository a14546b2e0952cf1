// Helpers shared by the LBM validation tests.
#pragma once

#include <cmath>
#include <vector>

#include "ship_lrm/lbm/solver.hpp"

namespace ship_lrm::lbm::test {

// Config with every face periodic.
LatticeConfig periodic_config(int nx, int ny, int nz, float nu);

// Taylor-Green vortex in the x-y plane, u = U (sin kx cos ky, -cos kx sin ky, 0), k = 2 pi / n,
// with its pressure field p = rho U^2 / 4 (cos 2kx + cos 2ky) (Taylor & Green 1937).
void taylor_green_2d(const Lattice& lat, float U, std::vector<float>& rho, std::vector<float>& u);

double total_mass(const Fields& f);
double kinetic_energy(const Fields& f);
double momentum(const Fields& f, int axis);

// Mean of u_axis over x and z as a function of y (profile across a channel in y).
std::vector<double> profile_y(const Lattice& lat, const Fields& f, int axis, int x_begin, int x_end);

}  // namespace ship_lrm::lbm::test
