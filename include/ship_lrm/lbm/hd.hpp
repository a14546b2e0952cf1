// Host/device annotation shared by the CPU (OpenMP) and CUDA backends, so every per-cell
// formula is written exactly once (ARCHITECTURE.md, "Core modules": lbm).
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

}  // namespace ship_lrm::lbm
