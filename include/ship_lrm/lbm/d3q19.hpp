// D3Q19 lattice descriptor (thesis section 6.1.2, Fig. 6.1 and Table 6.1).
// Ordering as in OpenLB (Krause et al. 2021) and the thesis' Table 6.1: directions 1..9 and
// 10..18 are opposite pairs (c_{i+9} = -c_i); weights 1/3 (rest), 1/18 (axis), 1/36 (diagonal).
#pragma once

#include "ship_lrm/lbm/hd.hpp"

namespace ship_lrm::lbm::d3q19 {

constexpr int Q = 19;
constexpr float cs2 = 1.0f / 3.0f;    // lattice speed of sound squared
constexpr float cs = 0.57735026919f;  // c_s = 1/sqrt(3)

SHIP_LRM_HD constexpr int cx(int i) {
  constexpr int t[Q] = {0, -1, 0, 0, -1, -1, -1, -1, 0, 0, 1, 0, 0, 1, 1, 1, 1, 0, 0};
  return t[i];
}
SHIP_LRM_HD constexpr int cy(int i) {
  constexpr int t[Q] = {0, 0, -1, 0, -1, 1, 0, 0, -1, -1, 0, 1, 0, 1, -1, 0, 0, 1, 1};
  return t[i];
}
SHIP_LRM_HD constexpr int cz(int i) {
  constexpr int t[Q] = {0, 0, 0, -1, 0, 0, -1, 1, -1, 1, 0, 0, 1, 0, 0, 1, -1, 1, -1};
  return t[i];
}
SHIP_LRM_HD constexpr int c(int i, int axis) { return axis == 0 ? cx(i) : (axis == 1 ? cy(i) : cz(i)); }
SHIP_LRM_HD constexpr float w(int i) {
  return i == 0 ? 1.0f / 3.0f : ((i == 1 || i == 2 || i == 3 || i == 10 || i == 11 || i == 12) ? 1.0f / 18.0f : 1.0f / 36.0f);
}
SHIP_LRM_HD constexpr int opp(int i) { return i == 0 ? 0 : (i <= 9 ? i + 9 : i - 9); }

// Index of the direction with the given lattice vector, or -1.
SHIP_LRM_HD constexpr int index_of(int x, int y, int z) {
  for (int i = 0; i < Q; ++i)
    if (cx(i) == x && cy(i) == y && cz(i) == z) return i;
  return -1;
}

}  // namespace ship_lrm::lbm::d3q19
