// 3-D laminar flow around a cylinder, benchmark 3D-1Z (steady, Re = 20) of Schaefer & Turek 1996,
// "Benchmark computations of laminar flow around a cylinder", Notes Numer. Fluid Mech. 52, 547:
// channel 2.5 x 0.41 x 0.41 m, cylinder D = 0.1 m on the z axis at (0.5, 0.2), inflow
// U = 16 Um y z (H - y)(H - z) / H^4 with Um = 0.45 m/s, nu = 1e-3 m^2/s, Re = Ubar D / nu = 20
// (Ubar = 4 Um / 9), c_D = 2 F_D / (rho Ubar^2 D H). Reference c_D = 6.18533 (Bayraktar, Mierka &
// Turek 2012, Int. J. Comput. Sci. Eng. 7, 253; the 1996 interval is 6.05 - 6.25).
#pragma once

#include <functional>

#include "ship_lrm/lbm/solver.hpp"

namespace ship_lrm::lbm {

constexpr double kSchaeferTurek3D1ZDrag = 6.18533;

struct CylinderBenchmarkResult {
  int cells_per_diameter = 0;
  long steps = 0;
  double drag_coefficient = 0;
  double lift_coefficient = 0;
  double relative_change = 0;  // of c_D over the last check interval (convergence)
  double seconds = 0;
  double mlups = 0;
};

// Runs until c_D changes by less than `tolerance` (relative) over one check interval or
// max_steps. progress(step, c_D) is called at every check when given.
CylinderBenchmarkResult run_cylinder_benchmark(int cells_per_diameter, Backend backend, long max_steps = 200000, double tolerance = 1e-4,
                                               const std::function<void(long, double)>& progress = {}, const std::string& vti_path = "");

}  // namespace ship_lrm::lbm
