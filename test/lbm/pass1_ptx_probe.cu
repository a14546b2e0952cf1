// Pass 1 of the open boundaries (update_boundary_state, even step) as a kernel of its own, compiled
// to PTX by check_pass1_ptx.sh: its PTX must use no local memory (docs/design.md, "The device's stack
// slot": nvcc 13.0 gave the boundary state's stack slot to other local arrays while it was live).
#include "ship_lrm/lbm/lattice_view.hpp"

__global__ void pass1_even(ship_lrm::lbm::LatticeView v) {
  const int b = blockIdx.x * blockDim.x + threadIdx.x;
  if (b < v.nbnd) ship_lrm::lbm::update_boundary_state<false>(v, b);
}
