// Newton trim of steady straight flight (see trim.hpp).
#include "ship_lrm/flight/trim.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

namespace ship_lrm::flight {
namespace {

using Vec6 = Eigen::Matrix<double, 6, 1>;

struct Evaluation {
  Vec6 residual;
  double main_power, tail_power, thrust, induced, download;
};

}  // namespace

RigidBodyState flight_state(const TrimTarget& t, double roll, double pitch) {
  RigidBodyState s;
  s.attitude = RigidBodyState::from_euler(roll, pitch, t.heading);
  const Vec3 v_ned(t.speed * std::cos(t.climb_angle) * std::cos(t.heading), t.speed * std::cos(t.climb_angle) * std::sin(t.heading),
                   -t.speed * std::sin(t.climb_angle));
  s.velocity = s.attitude.conjugate() * v_ned;
  return s;
}

TrimResult trim(Helicopter& heli, const TrimTarget& target, const TrimOptions& opt) {
  const auto& p = heli.parameters();
  const double g = p.mass.gravity;
  const double dt = p.time_step;
  const EngineMode mode = heli.engine().mode();
  heli.engine().set_mode(EngineMode::ConstantSpeed);
  heli.set_body_held(true);
  const int steps_per_rev = static_cast<int>(std::ceil(2.0 * M_PI / (heli.engine().reference_speed() * dt)));

  // unknowns x = (collective, forward, right, tail) [rad], roll, pitch [rad]
  Vec6 x;
  {
    BladeAngles a = map_controls(opt.initial_controls.value_or(PilotControls{}), p.controls, heli.right_pedal_increases_tail_pitch());
    if (!opt.initial_controls) {
      // blade-element-momentum estimate of the hover collective (Johnson, Rotorcraft Aeromechanics, 5.?):
      const double area = M_PI * p.main_rotor.radius * p.main_rotor.radius;
      const double tip = p.main_rotor.rotor_speed * p.main_rotor.radius;
      const double ct = p.mass.mass * g / (p.density * area * tip * tip);
      const double sigma = p.main_rotor.blades * p.main_rotor.chord / (M_PI * p.main_rotor.radius);
      a.main.collective = 6.0 * ct / (sigma * 5.7) + 1.5 * std::sqrt(ct / 2.0);
      a.main.forward = 0.02 * target.speed / 30.0;
      a.tail = 0.1;
    }
    const Vec3 att = opt.initial_attitude.value_or(Vec3(0, -0.002 * target.speed, 0));
    x << a.main.collective, a.main.forward, a.main.right, a.tail, att.x(), att.y();
  }
  const auto apply = [&](const Vec6& v) {
    BladeAngles a;
    a.main.collective = v[0];
    a.main.forward = v[1];
    a.main.right = v[2];
    a.tail = v[3];
    heli.set_blade_angles(a);
    heli.set_body(flight_state(target, v[4], v[5]));
  };
  bool first = true;
  const auto evaluate_once = [&](const Vec6& v, int settle) {
    apply(v);
    if (first) {
      heli.reset(flight_state(target, v[4], v[5]));
      first = false;
    } else {
      heli.inflow_model().reset(heli.disk_state());
    }
    for (int i = 0; i < settle * steps_per_rev; ++i) heli.step();
    Evaluation e{};
    e.residual.setZero();
    for (int i = 0; i < steps_per_rev; ++i) {
      heli.step();
      const auto& o = heli.outputs();
      e.residual.head<3>() += o.acceleration / g;
      e.residual.tail<3>() += o.angular_acceleration;
      e.main_power += o.main_power;
      e.tail_power += o.tail_power;
      e.thrust += -o.rotor.aero_force.z();
      e.induced += o.inflow.mean.z() + heli.disk_state().hub_velocity.z();
      e.download += o.airframe.fuselage.force.z();
    }
    const double inv = 1.0 / steps_per_rev;
    e.residual *= inv;
    e.main_power *= inv;
    e.tail_power *= inv;
    e.thrust *= inv;
    e.induced *= inv;
    e.download *= inv;
    if (!e.residual.allFinite()) throw std::runtime_error("non-finite trim residual");
    return e;
  };
  // A candidate far from trim can make the blade motion diverge; count it as a very bad candidate
  // and restart the rotor from rest at the next evaluation.
  const auto evaluate = [&](const Vec6& v, int settle) {
    try {
      return evaluate_once(v, settle);
    } catch (const std::runtime_error&) {
      first = true;
      Evaluation bad{};
      bad.residual.setConstant(1e3);
      return bad;
    }
  };

  const bool debug = std::getenv("SHIP_LRM_TRIM_DEBUG") != nullptr;
  TrimResult res;
  Evaluation cur = evaluate(x, opt.settle_revolutions + 3);
  Eigen::Matrix<double, 6, 6> jac;
  bool have_jac = false;
  const Vec6 h = (Vec6() << 2e-3, 2e-3, 2e-3, 4e-3, 2e-3, 2e-3).finished();
  for (res.iterations = 0; res.iterations < opt.max_iterations; ++res.iterations) {
    res.residual = cur.residual.norm();
    if (debug)
      std::fprintf(stderr, "trim %d: x = [%g %g %g %g %g %g] residual %g = [%g %g %g %g %g %g]\n", res.iterations, x[0], x[1], x[2], x[3],
                   x[4], x[5], res.residual, cur.residual[0], cur.residual[1], cur.residual[2], cur.residual[3], cur.residual[4],
                   cur.residual[5]);
    if (opt.progress) opt.progress(res.iterations, res.residual);
    if (!std::isfinite(res.residual)) break;
    if (res.residual < opt.tolerance) {
      res.converged = true;
      break;
    }
    if (!have_jac || res.iterations % 4 == 0) {
      for (int j = 0; j < 6; ++j) {
        Vec6 xp = x;
        xp[j] += h[j];
        jac.col(j) = (evaluate(xp, opt.settle_revolutions).residual - cur.residual) / h[j];
      }
      have_jac = true;
    }
    Vec6 dx = -jac.fullPivLu().solve(cur.residual);
    // limit the step (controls 2 deg, attitudes 3 deg) and back-track while the residual grows
    const double lim = std::max(dx.head<4>().cwiseAbs().maxCoeff() / 0.035, dx.tail<2>().cwiseAbs().maxCoeff() / 0.05);
    if (lim > 1) dx /= lim;
    double a = 1.0;
    Evaluation trial{};
    Vec6 xt;
    for (int k = 0; k < 5; ++k) {
      xt = x + a * dx;
      trial = evaluate(xt, opt.settle_revolutions);
      if (trial.residual.norm() < cur.residual.norm() || k == 4) break;
      a *= 0.5;
    }
    // Broyden rank-one update between Jacobian refreshes
    const Vec6 s = xt - x;
    if (s.norm() > 0) jac += (trial.residual - cur.residual - jac * s) * s.transpose() / s.squaredNorm();
    x = xt;
    cur = trial;
  }
  res.residual = cur.residual.norm();
  if (have_jac) res.jacobian = jac;
  apply(x);
  res.angles = heli.blade_angles();
  res.controls = heli.controls();
  res.roll = x[4];
  res.pitch = x[5];
  res.main_power = cur.main_power;
  res.tail_power = cur.tail_power;
  res.total_power = cur.main_power + cur.tail_power;
  res.thrust = cur.thrust;
  res.induced_velocity = cur.induced;
  res.download = cur.download;
  res.flapping = heli.main_rotor().multiblade_flap();
  res.body = heli.body();
  std::ostringstream os;
  if (res.converged)
    os << "trim converged at " << target.speed << " m/s in " << res.iterations << " iterations, residual " << res.residual;
  else
    os << "trim did NOT converge at " << target.speed << " m/s after " << res.iterations << " iterations: residual " << res.residual
       << " (tolerance " << opt.tolerance << ")";
  res.message = os.str();
  const auto c = heli.controls();
  if (c.collective < 0 || c.collective > 100 || c.longitudinal < 0 || c.longitudinal > 100 || c.lateral < 0 || c.lateral > 100 ||
      c.pedal < 0 || c.pedal > 100) {
    res.converged = false;
    res.message += "; the trimmed controls lie outside 0..100 % of travel";
  }
  heli.set_body_held(false);
  heli.engine().set_mode(mode);
  heli.engine().trim(heli.engine_state(), heli.outputs().rotor.aero_torque, heli.outputs().tail_power);
  return res;
}

}  // namespace ship_lrm::flight
