// Free vortex-ring wake of a uniformly loaded actuator disk (see free_wake_disk.hpp). Internally
// nondimensional: lengths in R, velocities in v_h, time in R / v_h, so a ring carries 2 dt.
#include "ship_lrm/rotor/free_wake_disk.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "ship_lrm/rotor/momentum_theory.hpp"

namespace ship_lrm::rotor {
namespace {

struct Ring {
  std::vector<Vec3> node;  // counter-clockwise about +z when shed: circulation > 0 drives the flow along +z
  double circulation;
  double age;
  int level;  // merged from 2^level shed rings
};

// The wake's segments in flat arrays, for vectorisable loops: single precision for the convection's
// O(n^2) Biot-Savart sum (its rounding, 1e-7 of a distance of order R, is far below the core), double
// for the flux through the disk.
struct Segments {
  std::vector<float> fax, fay, faz, flx, fly, flz, fl2, fgamma;  // l2 = |l|^2, gamma = Gamma / (4 pi)
  std::vector<double> ax, ay, az, lx, ly, lz, gamma;

  explicit Segments(const std::vector<Ring>& rings) {
    for (const auto& r : rings) {
      const std::size_t m = r.node.size();
      for (std::size_t i = 0; i < m; ++i) {
        const Vec3& a = r.node[i];
        const Vec3 l = r.node[(i + 1) % m] - a;
        const double g = r.circulation / (4.0 * M_PI);
        ax.push_back(a.x()), ay.push_back(a.y()), az.push_back(a.z());
        lx.push_back(l.x()), ly.push_back(l.y()), lz.push_back(l.z()), gamma.push_back(g);
        fax.push_back(static_cast<float>(a.x())), fay.push_back(static_cast<float>(a.y())), faz.push_back(static_cast<float>(a.z()));
        flx.push_back(static_cast<float>(l.x())), fly.push_back(static_cast<float>(l.y())), flz.push_back(static_cast<float>(l.z()));
        fl2.push_back(static_cast<float>(l.squaredNorm())), fgamma.push_back(static_cast<float>(g));
      }
    }
  }

  // Velocity induced at p: a straight vortex segment a -> a + l, r1 = p - a, r2 = p - a - l,
  // u = Gamma / (4 pi) (|r1| + |r2|) (r1 x r2) / (|r1| |r2| (|r1| |r2| + r1.r2) + eps^2 |l|^2)
  // (van Garrel 2003, ECN-C--03-079: the exact segment for eps = 0, finite on the filament).
  Vec3 velocity(const Vec3& p, double eps2) const {
    const float px = static_cast<float>(p.x()), py = static_cast<float>(p.y()), pz = static_cast<float>(p.z());
    const float e2 = static_cast<float>(eps2);
    const float* __restrict x = fax.data(), * __restrict y = fay.data(), * __restrict z = faz.data();
    const float* __restrict dx = flx.data(), * __restrict dy = fly.data(), * __restrict dz = flz.data();
    const float* __restrict l2 = fl2.data(), * __restrict g = fgamma.data();
    float ux = 0, uy = 0, uz = 0;
    const std::size_t n = fgamma.size();
#pragma omp simd reduction(+ : ux, uy, uz)
    for (std::size_t i = 0; i < n; ++i) {
      const float r1x = px - x[i], r1y = py - y[i], r1z = pz - z[i];
      const float r2x = r1x - dx[i], r2y = r1y - dy[i], r2z = r1z - dz[i];
      const float n1 = std::sqrt(r1x * r1x + r1y * r1y + r1z * r1z), n2 = std::sqrt(r2x * r2x + r2y * r2y + r2z * r2z);
      const float den = n1 * n2 * (n1 * n2 + r1x * r2x + r1y * r2y + r1z * r2z) + e2 * l2[i];
      const float f = den > 1e-30f ? g[i] * (n1 + n2) / den : 0.0f;
      ux += f * (r1y * r2z - r1z * r2y);
      uy += f * (r1z * r2x - r1x * r2z);
      uz += f * (r1x * r2y - r1y * r2x);
    }
    return {ux, uy, uz};
  }

  // Vector potential A(p) = sum Gamma / (4 pi) int dl / sqrt(|p - x|^2 + eps^2) over the segments; for a
  // segment with unit direction t, s0 = (p - a).t and h^2 = |p - a|^2 - s0^2 the integral is
  // asinh((|l| - s0) / H) + asinh(s0 / H), H = sqrt(h^2 + eps^2), taken as one logarithm:
  // asinh(x) = ln e(x), e(x) = x + sqrt(1 + x^2), written 1 / (sqrt(1 + x^2) - x) for x < 0 (no cancellation).
  Vec3 potential(const Vec3& p, double eps2) const {
    const double px = p.x(), py = p.y(), pz = p.z();
    const double* __restrict x = ax.data(), * __restrict y = ay.data(), * __restrict z = az.data();
    const double* __restrict dx = lx.data(), * __restrict dy = ly.data(), * __restrict dz = lz.data(), * __restrict g = gamma.data();
    double sx = 0, sy = 0, sz = 0;
    const std::size_t n = gamma.size();
    auto e = [](double v) {
      const double q = std::sqrt(1.0 + v * v);
      return v >= 0 ? v + q : 1.0 / (q - v);
    };
    for (std::size_t i = 0; i < n; ++i) {
      const double len = std::sqrt(dx[i] * dx[i] + dy[i] * dy[i] + dz[i] * dz[i]);
      const double tx = dx[i] / len, ty = dy[i] / len, tz = dz[i] / len;
      const double rx = px - x[i], ry = py - y[i], rz = pz - z[i];
      const double s0 = rx * tx + ry * ty + rz * tz;
      const double H = std::sqrt(std::max(0.0, rx * rx + ry * ry + rz * rz - s0 * s0) + eps2);
      const double I = g[i] * std::log(e((len - s0) / H) * e(s0 / H));
      sx += I * tx, sy += I * ty, sz += I * tz;
    }
    return {sx, sy, sz};
  }
};

// Mean induced velocity over the unit disk (along +z): the flux through it, the circulation of the
// vector potential round its edge (midpoint rule on `points` chords), over pi.
double disk_mean(const Segments& wake, int points) {
  // the flux integral's own regularisation: far below the distance of the nearest ring (half a step
  // from the edge), so that it does not smooth the field it measures
  constexpr double kEps2 = 1e-6;
  double flux = 0.0;
#pragma omp parallel for reduction(+ : flux) schedule(static)
  for (int k = 0; k < points; ++k) {
    const double t0 = 2.0 * M_PI * k / points, t1 = 2.0 * M_PI * (k + 1) / points, tm = 0.5 * (t0 + t1);
    const Vec3 dl(std::cos(t1) - std::cos(t0), std::sin(t1) - std::sin(t0), 0.0);
    flux += wake.potential(Vec3(std::cos(tm), std::sin(tm), 0.0), kEps2).dot(dl);
  }
  return flux / M_PI;
}

// Every node's velocity: the air plus the wake's induced velocity.
std::vector<std::vector<Vec3>> node_velocities(const std::vector<Ring>& rings, const Vec3& air, double eps2) {
  const Segments wake(rings);
  std::vector<std::vector<Vec3>> u(rings.size());
  std::vector<std::pair<int, int>> index;
  for (std::size_t r = 0; r < rings.size(); ++r) {
    u[r].resize(rings[r].node.size());
    for (std::size_t i = 0; i < rings[r].node.size(); ++i) index.emplace_back(static_cast<int>(r), static_cast<int>(i));
  }
  const long n = static_cast<long>(index.size());
#pragma omp parallel for schedule(static)
  for (long k = 0; k < n; ++k) {
    const auto [r, i] = index[k];
    u[r][i] = air + wake.velocity(rings[r].node[i], eps2);
  }
  return u;
}

// Two neighbouring rings of the same level, both older than merge_age 2^level, become one with their
// summed circulation at their mean position (equal circulations: the centroid of the vorticity).
void merge_far_wake(std::vector<Ring>& rings, double merge_age) {
  if (merge_age <= 0) return;
  for (std::size_t i = 0; i + 1 < rings.size(); ++i) {  // oldest first
    Ring& a = rings[i];
    const Ring& b = rings[i + 1];
    const double threshold = merge_age * std::ldexp(1.0, a.level);
    if (a.level != b.level || a.age < threshold || b.age < threshold) continue;
    for (std::size_t j = 0; j < a.node.size(); ++j) a.node[j] = 0.5 * (a.node[j] + b.node[j]);
    a.circulation += b.circulation;
    a.age = 0.5 * (a.age + b.age);
    a.level += 1;
    rings.erase(rings.begin() + static_cast<long>(i) + 1);
  }
}

// The wake's bookkeeping for one step, shared by the run and by work_per_step: every ring ages a step,
// the step's new ring (age half a step) joins, rings older than the wake age leave, old ones merge.
void age_shed_and_merge(std::vector<Ring>& rings, Ring fresh, const FreeWakeDiskConfig& c) {
  for (auto& r : rings) r.age += c.step;
  rings.push_back(std::move(fresh));
  while (!rings.empty() && rings.front().age > c.wake_age) rings.erase(rings.begin());
  merge_far_wake(rings, c.merge_age);
}

// The cumulative cost of the run up to each step, in units of ring pairs (the Biot-Savart sum is
// O(rings^2)): the same bookkeeping on rings without nodes.
std::vector<double> cumulative_work(const FreeWakeDiskConfig& c, long steps) {
  std::vector<Ring> rings;
  std::vector<double> work(static_cast<std::size_t>(steps) + 1, 0.0);
  for (long step = 1; step <= steps; ++step) {
    const double n = static_cast<double>(rings.size());
    work[static_cast<std::size_t>(step)] = work[static_cast<std::size_t>(step) - 1] + n * n + n;  // Heun's two sums, the new ring
    age_shed_and_merge(rings, Ring{{}, 0.0, 0.5 * c.step, 0}, c);
  }
  return work;
}

void check(const FreeWakeDiskConfig& c) {
  auto fail = [](const std::string& what) { throw std::invalid_argument("free-wake disk: " + what); };
  if (!(c.radius > 0) || !(c.thrust > 0) || !(c.density > 0)) fail("radius, thrust and density must be > 0");
  if (!c.air.allFinite()) fail("the air velocity must be finite");
  if (c.ring_points < 8 || c.ring_points > 4096) fail("ring points must lie in [8, 4096], got " + std::to_string(c.ring_points));
  if (!(c.step > 0 && c.step <= 0.2)) fail("the step must lie in (0, 0.2] R / v_h");
  if (!(c.core > 0 && c.core <= 0.5)) fail("the core must lie in (0, 0.5] R");
  if (!(c.wake_age >= 0.2 && c.wake_age <= 100.0)) fail("the wake age must lie in [0.2, 100] R / v_h");
  if (!(c.settle >= 0) || !(c.average > 0) || c.settle + c.average > 100.0)
    fail("settle must be >= 0, average > 0, and both together at most 100 R / v_h");
  if (c.edge_points < 16 || c.edge_points > 100000) fail("edge points must lie in [16, 100000]");
  if (c.wake_age / c.step > 20000) fail("more than 20000 rings (wake age / step): refine one, not both");
}

}  // namespace

void set_wake_lengths(FreeWakeDiskConfig& c, double spacing, double length, double merge_length) {
  if (!(spacing > 0) || !(length > spacing) || !(merge_length > 0))
    throw std::invalid_argument("free-wake disk: the ring spacing, wake length and merge length must be > 0, the length above the spacing");
  if (!(c.air.z() >= 0)) throw std::invalid_argument("free-wake disk: no wake lengths for a descent (air z < 0)");
  const double vh = hover_induced_velocity(c.thrust, c.density, c.radius);
  const double v = momentum_induced_velocity(c.thrust, c.density, c.radius, std::hypot(c.air.x(), c.air.y()), c.air.z());
  const double speed = std::hypot(c.air.x(), c.air.y(), c.air.z() + v) / vh;  // in v_h
  c.step = spacing / speed;
  c.wake_age = length / speed;
  c.merge_age = merge_length / speed;
}

FreeWakeDiskResult solve_free_wake_disk(const FreeWakeDiskConfig& c) {
  check(c);
  FreeWakeDiskResult res;
  res.hover = hover_induced_velocity(c.thrust, c.density, c.radius);
  // a descent (air passing the disk against the induced flow) leads to the vortex-ring and windmill
  // states, where the wake does not leave the disk steadily: outside this reference's scope
  if (c.air.z() < 0)
    throw std::invalid_argument(
        "free-wake disk: the air passes the disk against the induced flow (a descent, air z < 0); only "
        "level flight and climbs have a steady wake");
  res.momentum = momentum_induced_velocity(c.thrust, c.density, c.radius, std::hypot(c.air.x(), c.air.y()), c.air.z());
  const Vec3 air = c.air / res.hover;

  const int m = c.ring_points;
  const double dt = c.step, eps2 = c.core * c.core, shed = 2.0 * dt;  // dGamma/dt = dp / rho = 2 v_h^2
  std::vector<Vec3> edge(m);
  for (int i = 0; i < m; ++i) edge[i] = Vec3(std::cos(2.0 * M_PI * i / m), std::sin(2.0 * M_PI * i / m), 0.0);

  std::vector<Ring> rings;
  const double t_end = c.wake_age + c.settle + c.average, t_avg = c.wake_age + c.settle;
  const int sample_every = std::max(1, static_cast<int>(std::lround(0.05 / dt)));
  double sum = 0.0;
  int count = 0;
  res.min = 1e300, res.max = -1e300;
  long steps = 0;  // as many as the loop below takes
  while ((steps + 1) * dt <= t_end + 1e-9) ++steps;
  const std::vector<double> work = c.progress ? cumulative_work(c, steps) : std::vector<double>();
  for (long step = 1; step <= steps; ++step) {
    // Heun's method on every node
    if (!rings.empty()) {
      const auto k1 = node_velocities(rings, air, eps2);
      std::vector<Ring> predicted = rings;
      for (std::size_t r = 0; r < rings.size(); ++r)
        for (int i = 0; i < m; ++i) predicted[r].node[i] += dt * k1[r][i];
      const auto k2 = node_velocities(predicted, air, eps2);
      for (std::size_t r = 0; r < rings.size(); ++r)
        for (int i = 0; i < m; ++i) rings[r].node[i] += 0.5 * dt * (k1[r][i] + k2[r][i]);
    }
    // the circulation shed during this step, placed where its middle is: half a step from the edge
    // along the velocity there (the sheet's midpoint rule; a ring on the edge would make the flux
    // through the disk depend on its core)
    {
      const Segments wake(rings);
      Ring fresh{edge, shed, 0.5 * dt, 0};
      for (int i = 0; i < m; ++i) fresh.node[i] += 0.5 * dt * (air + wake.velocity(edge[i], eps2));
      age_shed_and_merge(rings, std::move(fresh), c);
    }
    for (const auto& r : rings)
      for (const auto& p : r.node)
        if (!p.allFinite() || p.norm() > 1e4)
          throw std::runtime_error("free-wake disk: the wake diverged at t = " + std::to_string(step * dt) +
                                   " R / v_h (try a smaller step or a larger core)");
    if (step % sample_every == 0 || step * dt > t_end - dt) {
      const double t = step * dt;
      const FreeWakeDiskSample s{t * c.radius / res.hover, disk_mean(Segments(rings), c.edge_points) * res.hover};
      res.history.push_back(s);
      if (t >= t_avg) {
        sum += s.mean, ++count;
        res.min = std::min(res.min, s.mean), res.max = std::max(res.max, s.mean);
      }
      if (c.progress) c.progress(work[static_cast<std::size_t>(step)] / std::max(1.0, work.back()), s.mean);
    }
    res.steps = step;
  }
  res.mean = count > 0 ? sum / count : res.history.back().mean;
  if (count == 0) res.min = res.max = res.mean;
  res.rings = static_cast<int>(rings.size());
  return res;
}

}  // namespace ship_lrm::rotor
