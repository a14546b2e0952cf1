// Carrying a flow over to a lattice whose walls moved (see refill.hpp).
#include "ship_lrm/lbm/refill.hpp"

namespace ship_lrm::lbm {

Fields carry_flow(const Lattice& was, const Fields& old) {
  const std::size_t n = was.cells();
  if (old.rho.size() != n || old.u.size() != 3 * n) throw ConfigError("carry_flow: the fields do not match the lattice");
  Fields out = old;
  const int nx = was.nx(), ny = was.ny(), nz = was.nz();
  std::vector<char> known(n);
  std::vector<std::size_t> todo;
  for (std::size_t c = 0; c < n; ++c) {
    known[c] = !is_wall(static_cast<CellType>(was.types()[c] & ~kGeneralBit));
    if (!known[c]) todo.push_back(c);
  }
  while (!todo.empty()) {
    std::vector<std::size_t> filled, left;
    for (std::size_t c : todo) {
      const int i = static_cast<int>(c % nx), j = static_cast<int>((c / nx) % ny);
      const int k = static_cast<int>(c / (static_cast<std::size_t>(nx) * ny));
      double r = 0, m = 0, v[3] = {0, 0, 0};
      for (int q = 1; q < d3q19::Q; ++q) {
        const int a = i + d3q19::cx(q), b = j + d3q19::cy(q), e = k + d3q19::cz(q);
        if (a < 0 || b < 0 || e < 0 || a >= nx || b >= ny || e >= nz) continue;
        const std::size_t nb = was.index(a, b, e);
        if (!known[nb]) continue;
        r += out.rho[nb];
        for (int d = 0; d < 3; ++d) v[d] += out.u[3 * nb + d];
        ++m;
      }
      if (m == 0) {
        left.push_back(c);
        continue;
      }
      out.rho[c] = static_cast<float>(r / m);
      for (int d = 0; d < 3; ++d) out.u[3 * c + d] = static_cast<float>(v[d] / m);
      filled.push_back(c);
    }
    if (filled.empty()) break;  // no fluid at all: leave the rest at rest
    for (std::size_t c : filled) known[c] = 1;
    todo.swap(left);
  }
  for (std::size_t c : todo) {
    out.rho[c] = 1.0f;
    out.u[3 * c] = out.u[3 * c + 1] = out.u[3 * c + 2] = 0.0f;
  }
  return out;
}

}  // namespace ship_lrm::lbm
