// Isolated rotor in the LRM domain against Pitt-Peters / momentum theory (see inflow_sweep.hpp).
#include "ship_lrm/lrm/inflow_sweep.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <sstream>
#include <vector>

#include "ship_lrm/rotor/momentum_theory.hpp"
#include "ship_lrm/rotor/pitt_peters.hpp"

namespace ship_lrm::lrm {

namespace {

// The case's domain with its stream and walls, the flow not yet started: what run_isolated_rotor
// steps and check_isolated_rotor only builds. ConfigError for a set-up that cannot run;
// ground_effective_height: where the bounce-back wall lies (m below the hub; 0 without a ground).
std::unique_ptr<LrmDomain> case_domain(const LrmConfig& cfg, const IsolatedRotorCase& c, double& ground_effective_height) {
  if (!(c.settle >= 0) || !(c.average > 0)) throw ConfigError("isolated rotor: needs settle >= 0 s and average > 0 s");
  if (!(c.thrust > 0)) throw ConfigError("isolated rotor: needs a thrust > 0 N");
  if (!(c.ground_height >= 0)) throw ConfigError("isolated rotor: the ground height must be >= 0 m (0: no ground)");
  if (!(c.climb >= 0) || !std::isfinite(c.climb))
    throw ConfigError("isolated rotor: the climb rate must be a finite number >= 0 m/s (descents are not supported)");
  if (c.slip_ground && !(c.ground_height > 0)) throw ConfigError("isolated rotor: a slip ground needs a ground (a height > 0 m)");
  if (c.climb > 0 && c.ground_height > 0)
    throw ConfigError("isolated rotor: a climb over a ground plane has no steady state; give either a climb rate or a ground");
  auto domain = std::make_unique<LrmDomain>(cfg);
  LrmDomain& d = *domain;
  d.set_stream(Vec3(-c.speed, 0, c.climb));
  if (c.fuselage) d.add_wall(std::make_shared<Fuselage>());
  ground_effective_height = 0;
  if (c.ground_height > 0) {
    const double half = 0.5 * (d.cells_per_edge() - 1) * d.units().dx();
    if (c.ground_height > half - 3 * d.units().dx()) {
      std::ostringstream what;
      what << "isolated rotor: a ground " << c.ground_height << " m below the hub lies outside the domain (" << half
           << " m to the bottom face, the ground at least three cells above it); raise the reach a or lower the height";
      throw ConfigError(what.str());
    }
    auto ground = std::make_shared<GroundPlane>(c.ground_height);
    RigidMotion m;
    m.velocity = Vec3(-c.speed, 0, 0);  // the ground passes under the rotor at the flight speed
    ground->set_motion(m);
    ground->set_slip(c.slip_ground);
    d.add_wall(ground);
    // first wall cell below the hub: cell centres k with (k - centre) dx > height
    const double centre = 0.5 * (d.cells_per_edge() - 1);
    const double k0 = std::floor(centre + c.ground_height / d.units().dx()) + 1.0;
    ground_effective_height = (k0 - 0.5 - centre) * d.units().dx();
    if (cfg.rotor_far_field) d.set_far_field_ground(ground_effective_height);
  }
  return domain;
}

}  // namespace

void check_isolated_rotor(const LrmConfig& cfg, const IsolatedRotorCase& c) {
  double ground_effective_height;
  case_domain(cfg, c, ground_effective_height);
}

IsolatedRotorResult run_isolated_rotor(const LrmConfig& cfg, const IsolatedRotorCase& c) {
  IsolatedRotorResult r;
  const std::unique_ptr<LrmDomain> domain = case_domain(cfg, c, r.ground_effective_height);
  LrmDomain& d = *domain;
  d.restart_flow();
  rotor::RotorForceHarmonics h;
  h.cos[0] = Vec3(0, 0, -c.thrust);
  d.set_rotor_forces(h);
  r.cells_per_edge = d.cells_per_edge();
  const auto t0 = std::chrono::steady_clock::now();
  const long settle = static_cast<long>(std::ceil(c.settle / d.time_step()));
  const long every = std::max(1L, static_cast<long>(std::lround(0.05 / d.time_step())));  // sample every ~0.05 s
  const long samples = std::max(1L, static_cast<long>(std::ceil(c.average / (every * d.time_step()))));
  const long total = std::max(1L, settle) + samples * every;
  long done = 0;
  const auto advance = [&](long n) {
    d.step(n);
    done += n;
    if (c.progress) c.progress(static_cast<double>(done) / static_cast<double>(total));
  };
  for (long left = std::max(1L, settle); left > 0; left -= every) advance(std::min(left, every));
  std::vector<double> induced(static_cast<size_t>(samples));
  SliceAverage plane;
  for (long k = 0; k < samples; ++k) {
    advance(every);
    const rotor::RotorInflow in = d.inflow();
    r.inflow.mean += in.mean / samples;
    r.inflow.sine += in.sine / samples;
    r.inflow.cosine += in.cosine / samples;
    induced[static_cast<size_t>(k)] = in.mean.z() - c.climb;
    if (c.centre_plane) plane.add(domain_slice(d, 1));
  }
  if (c.centre_plane) r.centre_plane = plane.mean();
  r.induced_mean = r.inflow.mean.z() - c.climb;
  double square = 0, first = 0, second = 0;
  const long half = samples / 2;
  for (long k = 0; k < samples; ++k) {
    const double v = induced[static_cast<size_t>(k)];
    square += (v - r.induced_mean) * (v - r.induced_mean);
    if (k < half) first += v / half;
    if (k >= samples - half && half > 0) second += v / half;
  }
  r.induced_std = samples > 1 ? std::sqrt(square / (samples - 1)) : 0.0;
  r.induced_half_difference = second - first;
  r.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.steps = d.solver().steps_done();
  r.simulated_seconds = d.time();
  rotor::RotorDiskState s;
  s.radius = cfg.radius;
  s.rotor_speed = c.rotor_speed;
  s.density = cfg.density;
  s.hub_velocity = Vec3(c.speed, 0, -c.climb);  // the hub moves up (-z) in a climb
  s.aero_force = Vec3(0, 0, -c.thrust);
  const Eigen::Vector3d lam = rotor::PittPetersInflow::steady_states(s, Eigen::Vector3d::Zero());
  r.pitt_peters_mean = lam[0] * c.rotor_speed * cfg.radius;
  r.pitt_peters_cosine = lam[2] * c.rotor_speed * cfg.radius;
  r.momentum_theory = rotor::momentum_induced_velocity(c.thrust, cfg.density, cfg.radius, c.speed, c.climb);
  return r;
}

double cheeseman_bennett_ratio(double z_over_R, double speed, double induced_velocity) {
  const double g = 1.0 / (16.0 * z_over_R * z_over_R);
  const double q = induced_velocity > 0 ? speed / induced_velocity : 0.0;
  return 1.0 - g / (1.0 + q * q);
}

double hayden_ratio(double z_over_R) { return 1.0 / (0.9926 + 0.0379 * 4.0 / (z_over_R * z_over_R)); }

}  // namespace ship_lrm::lrm
