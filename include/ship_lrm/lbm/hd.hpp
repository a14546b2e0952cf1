// Host/device annotation shared by the CPU (OpenMP) and CUDA backends, so every per-cell
// formula is written exactly once (docs/design.md, "One source of physics").
#pragma once

#if defined(__CUDACC__)
#define SHIP_LRM_HD __host__ __device__ __forceinline__
#elif defined(__GNUC__)
#define SHIP_LRM_HD inline __attribute__((always_inline))  // so the bulk loop inlines and vectorises
#else
#define SHIP_LRM_HD inline
#endif

namespace ship_lrm::lbm {

// Storage type of the populations: a build parameter (float32 now; a float16 storage with float32
// arithmetic is planned, which only needs these two conversion functions to change).
#ifndef SHIP_LRM_POP_STORAGE
#define SHIP_LRM_POP_STORAGE float
#endif
using pop_t = SHIP_LRM_POP_STORAGE;

SHIP_LRM_HD float load_pop(pop_t v) { return static_cast<float>(v); }
SHIP_LRM_HD pop_t store_pop(float v) { return static_cast<pop_t>(v); }

// Component `axis` (0, 1 or 2, known only at run time) of a small local vector, read and written by
// selection instead of by index. A local array indexed by a run-time value lives in the device's
// local memory (the stack), and there nvcc 13.0 reused the slot of the open-boundary pass's state (a
// Macro returned by value) for other local arrays while the state was still live: pass 1 read an
// integer coordinate as the normal velocity and took the inflow branch at every cell of the back
// face (docs/design.md, "The device's stack slot"). Selected, the vector stays in registers.
template <class T>
SHIP_LRM_HD T component(const T v[3], int axis) {
  return axis == 0 ? v[0] : (axis == 1 ? v[1] : v[2]);
}
template <class T>
SHIP_LRM_HD void set_component(T v[3], int axis, T value) {
  v[0] = axis == 0 ? value : v[0];
  v[1] = axis == 1 ? value : v[1];
  v[2] = axis == 2 ? value : v[2];
}

}  // namespace ship_lrm::lbm
