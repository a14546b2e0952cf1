// Forces of listed cells as a sum of per-cell columns: f_k = sum_m c_m basis_m[k], with a vector
// coefficient c_m (3 components) per column m. The rotor disk's force (thesis 6.5) has this form: the
// columns are eps / A, eps / A cos(k psi) and eps / A sin(k psi) of each disk cell, the coefficients the
// harmonics of the blade forces (rotor/disk_coupling.hpp). Written once for the host's DiskCoupling
// (double), the solver's host path and the CUDA kernel (float), so that every backend sums the same
// terms in the same order.
#pragma once

#include <cstddef>

#include "ship_lrm/lbm/hd.hpp"

namespace ship_lrm::lbm {

// The most columns a solver takes (Solver::set_cell_force_columns): the disk's 1 + 2 x 9 harmonics
// with room to spare; the CUDA backend passes the coefficients as a kernel argument of this size.
constexpr int kMaxForceColumns = 32;

// For listed cells k0 <= k < k1 of n (basis[m * n + k], m < columns; coefficients[3 m + a]):
// out[a * stride + (k - k0)] = sum over m, in ascending order, of coefficients[3 m + a] basis[m * n + k].
// A column whose coefficient component is zero is skipped (a hover's higher harmonics cost nothing);
// the result is the same. The cells are the inner loop, so the host's sum over many cells vectorises.
template <class T>
SHIP_LRM_HD void column_series(const T* basis, std::size_t n, std::size_t k0, std::size_t k1, int columns, const T* coefficients, T* out,
                               std::size_t stride) {
  for (int a = 0; a < 3; ++a)
    for (std::size_t k = k0; k < k1; ++k) out[a * stride + (k - k0)] = T(0);
  for (int m = 0; m < columns; ++m) {
    const T* column = basis + m * n;
    for (int a = 0; a < 3; ++a) {
      const T c = coefficients[3 * m + a];
      if (c == T(0)) continue;
      T* f = out + a * stride;
      for (std::size_t k = k0; k < k1; ++k) f[k - k0] += c * column[k];
    }
  }
}

}  // namespace ship_lrm::lbm
