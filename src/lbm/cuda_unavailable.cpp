// Built when the CUDA backend is not compiled in (no nvcc or SHIP_LRM_CUDA=OFF).
#include "ship_lrm/lbm/benchmark.hpp"
#include "ship_lrm/lbm/solver.hpp"

namespace ship_lrm::lbm {

bool cuda_available() { return false; }

std::unique_ptr<Solver> make_cuda_solver(Lattice) {
  throw ConfigError(
      "backend 'cuda' requested, but ship_lrm was built without CUDA (configure with nvcc on the PATH or -DSHIP_LRM_CUDA=ON)");
}

double device_copy_bandwidth_gbs(std::size_t) { throw ConfigError("device bandwidth: built without CUDA"); }
double device_inplace_bandwidth_gbs(std::size_t) { throw ConfigError("device bandwidth: built without CUDA"); }

}  // namespace ship_lrm::lbm
