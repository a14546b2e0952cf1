// Difference of two backends' fields, with the worst cell named, so that a device test that fails
// says where (the CUDA-against-CPU tests of the LBM, LRM and wake feed).
#pragma once

#include <cmath>
#include <cstdio>
#include <string>

#include "ship_lrm/lbm/solver.hpp"

namespace ship_lrm::lbm::test {

struct BackendDifference {
  double du = 0;                      // largest |u_a - u_b| over the largest |u_a|
  double drho = 0;                    // largest |rho_a - rho_b| / rho_a
  int x = 0, y = 0, z = 0, type = 0;  // the cell of the largest velocity difference
  std::string text;                   // the above in words
};

inline BackendDifference backend_difference(const Lattice& lat, const Fields& a, const Fields& b) {
  BackendDifference d;
  double umax = 0, du = 0;
  std::size_t worst = 0;
  for (std::size_t k = 0; k < a.u.size() && k < b.u.size(); ++k) {
    umax = std::max(umax, static_cast<double>(std::abs(a.u[k])));
    const double e = std::abs(a.u[k] - b.u[k]);
    if (e > du) du = e, worst = k / 3;
  }
  for (std::size_t k = 0; k < a.rho.size() && k < b.rho.size(); ++k)
    d.drho = std::max(d.drho, static_cast<double>(std::abs(a.rho[k] - b.rho[k]) / a.rho[k]));
  d.du = umax > 0 ? du / umax : du;
  d.x = static_cast<int>(worst % lat.nx());
  d.y = static_cast<int>(worst / lat.nx() % lat.ny());
  d.z = static_cast<int>(worst / (static_cast<std::size_t>(lat.nx()) * lat.ny()));
  d.type = static_cast<int>(lat.types()[worst]);
  char s[200];
  std::snprintf(s, sizeof s, "max |du| / max |u| = %.3g (cell %d %d %d, type %d), max |drho| / rho = %.3g", d.du, d.x, d.y, d.z, d.type,
                d.drho);
  d.text = s;
  return d;
}

}  // namespace ship_lrm::lbm::test
