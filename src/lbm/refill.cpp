// Carrying a flow over to a lattice whose walls moved (see refill.hpp).
#include "ship_lrm/lbm/refill.hpp"

namespace ship_lrm::lbm {

std::vector<std::array<float, 4>> refill_states(const Lattice& was, const std::vector<std::uint32_t>& cells,
                                                const std::function<std::array<float, 4>(std::size_t)>& state) {
  const std::size_t n = was.cells();
  const int nx = was.nx(), ny = was.ny(), nz = was.nz();
  const auto fluid_before = [&](std::size_t c) { return !is_wall(static_cast<CellType>(was.types()[c] & ~kGeneralBit)); };
  std::vector<std::array<float, 4>> out(cells.size(), std::array<float, 4>{1.0f, 0.0f, 0.0f, 0.0f});
  std::vector<std::int64_t> slot(n, -1);  // cell -> its place in `cells`
  for (std::size_t k = 0; k < cells.size(); ++k) {
    if (cells[k] >= n) throw ConfigError("refill_states: cell index out of range");
    slot[cells[k]] = static_cast<std::int64_t>(k);
  }
  std::vector<char> filled(cells.size(), 0);
  std::vector<std::size_t> todo;
  for (std::size_t k = 0; k < cells.size(); ++k)
    if (!fluid_before(cells[k])) todo.push_back(k);
  for (std::size_t k = 0; k < cells.size(); ++k)
    if (fluid_before(cells[k])) out[k] = state(cells[k]), filled[k] = 1;  // not a refill: the cell's own state
  while (!todo.empty()) {
    std::vector<std::size_t> front, left;
    for (std::size_t k : todo) {
      const std::size_t c = cells[k];
      const int i = static_cast<int>(c % nx), j = static_cast<int>((c / nx) % ny);
      const int l = static_cast<int>(c / (static_cast<std::size_t>(nx) * ny));
      double sum[4] = {0, 0, 0, 0}, m = 0;
      for (int q = 1; q < d3q19::Q; ++q) {
        const int a = i + d3q19::cx(q), b = j + d3q19::cy(q), e = l + d3q19::cz(q);
        if (a < 0 || b < 0 || e < 0 || a >= nx || b >= ny || e >= nz) continue;
        const std::size_t nb = was.index(a, b, e);
        std::array<float, 4> s;
        if (fluid_before(nb))
          s = state(nb);
        else if (slot[nb] >= 0 && filled[slot[nb]])
          s = out[slot[nb]];
        else
          continue;
        for (int d = 0; d < 4; ++d) sum[d] += s[d];
        ++m;
      }
      if (m == 0) {
        left.push_back(k);
        continue;
      }
      for (int d = 0; d < 4; ++d) out[k][d] = static_cast<float>(sum[d] / m);
      front.push_back(k);
    }
    if (front.empty()) break;                   // no fluid reachable: the rest stays at rest
    for (std::size_t k : front) filled[k] = 1;  // after the front: each cell of a front sees only earlier ones
    todo.swap(left);
  }
  return out;
}

Fields restart_fields(const Lattice& was, Fields old, const std::vector<std::uint32_t>& freed) {
  const std::size_t n = was.cells();
  if (old.rho.size() != n || old.u.size() != 3 * n) throw ConfigError("carrying the flow over: the fields do not match the lattice");
  const auto states = refill_states(was, freed, [&](std::size_t c) {
    return std::array<float, 4>{old.rho[c], old.u[3 * c], old.u[3 * c + 1], old.u[3 * c + 2]};
  });
  for (std::size_t k = 0; k < freed.size(); ++k) {
    old.rho[freed[k]] = states[k][0];
    for (int d = 0; d < 3; ++d) old.u[3 * freed[k] + d] = states[k][1 + d];
  }
  return old;
}

Fields carry_flow(const Lattice& was, const Fields& old) {
  std::vector<std::uint32_t> walls;
  for (std::size_t c = 0; c < was.cells(); ++c)
    if (is_wall(static_cast<CellType>(was.types()[c] & ~kGeneralBit))) walls.push_back(static_cast<std::uint32_t>(c));
  return restart_fields(was, old, walls);
}

}  // namespace ship_lrm::lbm
