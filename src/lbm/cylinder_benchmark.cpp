#include "ship_lrm/lbm/cylinder_benchmark.hpp"

#include <chrono>
#include <cmath>

#include "ship_lrm/lbm/vtk_writer.hpp"
#include "ship_lrm/lbm/wall_force.hpp"

namespace ship_lrm::lbm {

CylinderBenchmarkResult run_cylinder_benchmark(int D, Backend backend, long max_steps, double tolerance,
                                               const std::function<void(long, double)>& progress, const std::string& vti_path) {
  if (D < 4 || D > 80) throw ConfigError("cylinder benchmark: cells per diameter must lie in [4, 80]");
  const double dx = 0.1 / D;                               // [m]
  const int H = static_cast<int>(std::lround(0.41 / dx));  // cells across the channel (walls halfway outside)
  const int nx = static_cast<int>(std::lround(2.5 / dx)) + 1;
  const float um = 0.1f;  // lattice centre-line velocity (Mach 0.17)
  const double ubar = 4.0 * um / 9.0;
  LatticeConfig cfg;
  cfg.nx = nx;
  cfg.ny = H;
  cfg.nz = H;
  cfg.collision.nu = static_cast<float>(ubar * D / 20.0);  // Re = 20
  cfg.faces[0].type = FaceType::VelocityInlet;
  cfg.faces[1].type = FaceType::PressureOutlet;
  for (int f = 2; f < 6; ++f) cfg.faces[f].type = FaceType::Wall;
  cfg.guard_interval = 500;
  Lattice lat(cfg);
  std::vector<char> body(lat.cells(), 0);
  // Halfway bounce-back puts the wall midway between the last fluid and the first solid cell, so
  // solid cells are those within r - 1/2 of the axis: the wall then lies at about r.
  const double cx = 0.5 / dx, cy = 0.2 / dx - 0.5, r = 0.5 * D - 0.5;
  for (int z = 0; z < H; ++z)
    for (int y = 0; y < H; ++y)
      for (int x = 0; x < nx; ++x)
        if ((x - cx) * (x - cx) + (y - cy) * (y - cy) <= r * r) {
          lat.set_wall(x, y, z);
          body[lat.index(x, y, z)] = 1;
        }
  // inflow profile at the cell centres y = (j + 1/2) dx
  for (int z = 0; z < H; ++z)
    for (int y = 0; y < H; ++y) {
      const double yy = (y + 0.5) / H, zz = (z + 0.5) / H;
      lat.set_velocity_inlet(0, y, z, {static_cast<float>(16.0 * um * yy * zz * (1 - yy) * (1 - zz)), 0.0f, 0.0f});
    }
  auto solver = make_solver(std::move(lat), backend);
  const double norm = 2.0 / (ubar * ubar * D * H);
  const long interval = 2 * static_cast<long>(std::lround(0.25 * D * D / cfg.collision.nu / 2.0)) + 2;  // ~ D^2 / (4 nu), even
  CylinderBenchmarkResult res;
  res.cells_per_diameter = D;
  double last = 0;
  const auto t0 = std::chrono::steady_clock::now();
  while (solver->steps_done() < max_steps) {
    solver->step(interval);
    const auto F = wall_force(*solver, body);
    res.drag_coefficient = F[0] * norm;
    res.lift_coefficient = F[1] * norm;
    res.relative_change = std::abs(res.drag_coefficient - last) / std::abs(res.drag_coefficient);
    last = res.drag_coefficient;
    if (progress) progress(solver->steps_done(), res.drag_coefficient);
    if (solver->steps_done() > 4 * interval && res.relative_change < tolerance) break;
  }
  res.steps = solver->steps_done();
  res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  res.mlups = static_cast<double>(solver->lattice().cells()) * res.steps / res.seconds * 1e-6;
  if (!vti_path.empty()) write_vti(vti_path, solver->lattice(), solver->fields(), dx);
  return res;
}

}  // namespace ship_lrm::lbm
