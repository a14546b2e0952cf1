// Stability probe of a uniform stream (see stream_stability.hpp).
#include "ship_lrm/lbm/stream_stability.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

namespace ship_lrm::lbm {

double StreamStabilityResult::growth() const {
  if (diverged) return std::numeric_limits<double>::infinity();
  if (samples.size() < 2 || samples.front().max_deviation <= 0) return 1.0;
  return samples.back().max_deviation / samples.front().max_deviation;
}

StreamStabilityResult run_stream_stability(const StreamStabilityCase& c) {
  if (c.size < 4 || c.size > 512) throw ConfigError("stream stability: the box edge must lie in [4, 512] cells");
  if (!(c.mach >= 0.0f) || c.mach > kMaxSetupMach)
    throw ConfigError("stream stability: the Mach number must lie in [0, " + std::to_string(kMaxSetupMach) + "]");
  if (!(c.nu > 0.0f)) throw ConfigError("stream stability: the lattice viscosity must be > 0");
  if (!(c.smagorinsky >= 0.0f)) throw ConfigError("stream stability: the Smagorinsky constant must be >= 0");
  if (!(c.amplitude > 0.0f) || c.amplitude > 0.01f) throw ConfigError("stream stability: the amplitude must lie in (0, 0.01]");
  if (c.steps < 1 || c.sample_interval < 1) throw ConfigError("stream stability: steps and the sample interval must be >= 1");
  const int n = c.size;
  LatticeConfig cfg;
  cfg.nx = cfg.ny = cfg.nz = n;
  cfg.collision.nu = c.nu;
  cfg.collision.smagorinsky = c.smagorinsky;
  cfg.collision.model = c.collision;
  const double U = c.mach / std::sqrt(3.0);
  for (auto& f : cfg.faces) f.type = FaceType::Periodic;
  const bool open = c.faces == StreamStabilityCase::Faces::InletOutlet;
  if (open) {
    cfg.faces[0].type = FaceType::VelocityInlet;
    cfg.faces[0].velocity = {static_cast<float>(U), 0.0f, 0.0f};
    cfg.faces[0].characteristic_inlet = c.characteristic_inlet;
    cfg.faces[0].absorbing_cells = c.absorbing_cells;
    cfg.faces[0].absorbing_strength = 0.5f;
    cfg.faces[1].type = FaceType::PressureOutlet;
  }
  cfg.guard_interval = 16;
  auto solver = make_solver(Lattice(cfg), c.backend);
  const std::size_t cells = solver->lattice().cells();
  std::vector<double> wave(n);  // sin(k y), k = 2 pi / n: the shear wave's profile
  for (int y = 0; y < n; ++y) wave[y] = std::sin(2.0 * M_PI * y / n);
  std::vector<float> rho(cells, 1.0f), u(3 * cells, 0.0f);
  std::mt19937 rng(c.random_seed);
  std::uniform_real_distribution<float> noise(-c.amplitude, c.amplitude);
  for (int z = 0; z < n; ++z)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        float* v = &u[3 * solver->lattice().index(x, y, z)];
        v[0] = static_cast<float>(U);
        if (open && (x == 0 || x == n - 1)) continue;  // the faces' cells hold the prescribed stream
        if (c.seed == StreamStabilityCase::Seed::ShearWave)
          v[0] += c.amplitude * static_cast<float>(wave[y]);
        else
          for (int a = 0; a < 3; ++a) v[a] += noise(rng);
      }
  solver->initialize(rho, u);
  StreamStabilityResult r;
  auto sample = [&]() {
    const Fields f = solver->fields();
    StreamStabilitySample s;
    s.step = solver->steps_done();
    double sine = 0;
    for (int z = 0; z < n; ++z)
      for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
          const float* v = &f.u[3 * solver->lattice().index(x, y, z)];
          const double dx = v[0] - U;
          s.max_deviation = std::max(s.max_deviation, std::sqrt(dx * dx + v[1] * v[1] + v[2] * v[2]));
          sine += dx * wave[y];
        }
    s.shear_amplitude = 2.0 * sine / cells;
    r.samples.push_back(s);
  };
  sample();
  while (solver->steps_done() < c.steps) {
    try {
      solver->step(std::min(c.sample_interval, c.steps - solver->steps_done()));
    } catch (const DivergenceError& e) {
      r.diverged = true;
      r.diverged_at = e.step;
      return r;
    }
    sample();
  }
  return r;
}

}  // namespace ship_lrm::lbm
