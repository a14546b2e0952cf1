#include "flow_cases.hpp"

namespace ship_lrm::lbm::test {

LatticeConfig periodic_config(int nx, int ny, int nz, float nu) {
  LatticeConfig cfg;
  cfg.nx = nx;
  cfg.ny = ny;
  cfg.nz = nz;
  for (auto& f : cfg.faces) f.type = FaceType::Periodic;
  cfg.collision.nu = nu;
  return cfg;
}

void taylor_green_2d(const Lattice& lat, float U, std::vector<float>& rho, std::vector<float>& u) {
  const std::size_t n = lat.cells();
  rho.assign(n, 1.0f);
  u.assign(3 * n, 0.0f);
  const double kx = 2 * M_PI / lat.nx(), ky = 2 * M_PI / lat.ny();
  for (int z = 0; z < lat.nz(); ++z)
    for (int y = 0; y < lat.ny(); ++y)
      for (int x = 0; x < lat.nx(); ++x) {
        const std::size_t c = lat.index(x, y, z);
        u[3 * c] = static_cast<float>(U * std::sin(kx * x) * std::cos(ky * y));
        u[3 * c + 1] = static_cast<float>(-U * std::cos(kx * x) * std::sin(ky * y));
        // p = cs^2 (rho - 1)
        rho[c] = static_cast<float>(1.0 + 3.0 * U * U / 4.0 * (std::cos(2 * kx * x) + std::cos(2 * ky * y)));
      }
}

double total_mass(const Fields& f) {
  double m = 0;
  for (float r : f.rho) m += r;
  return m;
}

double kinetic_energy(const Fields& f) {
  double e = 0;
  for (std::size_t c = 0; c < f.rho.size(); ++c)
    e += 0.5 * f.rho[c] * (f.u[3 * c] * f.u[3 * c] + f.u[3 * c + 1] * f.u[3 * c + 1] + f.u[3 * c + 2] * f.u[3 * c + 2]);
  return e;
}

double momentum(const Fields& f, int axis) {
  double p = 0;
  for (std::size_t c = 0; c < f.rho.size(); ++c) p += static_cast<double>(f.rho[c]) * f.u[3 * c + axis];
  return p;
}

std::vector<double> profile_y(const Lattice& lat, const Fields& f, int axis, int x_begin, int x_end) {
  std::vector<double> p(lat.ny(), 0.0);
  for (int y = 0; y < lat.ny(); ++y) {
    double s = 0;
    int n = 0;
    for (int z = 0; z < lat.nz(); ++z)
      for (int x = x_begin; x < x_end; ++x, ++n) s += f.u[3 * lat.index(x, y, z) + axis];
    p[y] = s / n;
  }
  return p;
}

}  // namespace ship_lrm::lbm::test
