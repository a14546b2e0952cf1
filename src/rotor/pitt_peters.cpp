// Pitt-Peters three-state dynamic inflow; equations and sources in pitt_peters.hpp.
#include "ship_lrm/rotor/pitt_peters.hpp"

#include <Eigen/Dense>
#include <cmath>

namespace ship_lrm::rotor {
namespace {

struct Coefficients {
  Eigen::Vector3d loads;  // C_T, C_s, C_c
  double mu, lambda_free;
};

Coefficients coefficients(const RotorDiskState& s) {
  const double area = M_PI * s.radius * s.radius;
  const double tip = s.rotor_speed * s.radius;
  const double q = s.density * area * tip * tip;
  Coefficients c;
  c.loads = Eigen::Vector3d(-s.aero_force.z() / q, -s.aero_moment.x() / (q * s.radius), -s.aero_moment.y() / (q * s.radius));
  c.mu = std::hypot(s.hub_velocity.x(), s.hub_velocity.y()) / tip;
  c.lambda_free = -s.hub_velocity.z() / tip;  // air through the disk from the hub's own motion
  return c;
}

// V Ltilde^-1 lambda (the "damping" side of the Pitt-Peters equation).
Eigen::Vector3d flow_term(const Coefficients& c, const Eigen::Vector3d& lam) {
  const double lambda = c.lambda_free + lam[0];
  // A floor keeps the start from zero inflow in hover well posed (V_T -> 0 there).
  const double vt = std::max(std::sqrt(c.mu * c.mu + lambda * lambda), 1e-4);
  const double vm = std::max((c.mu * c.mu + lambda * (lambda + lam[0])) / vt, 1e-4);
  const double chi = std::atan2(c.mu, std::abs(lambda));
  const double x = std::tan(0.5 * chi);
  Eigen::Matrix3d lt;
  const double k = 15.0 * M_PI / 64.0 * x;
  lt << 0.5, 0, -k, 0, 2.0 * (1 + x * x), 0, k, 0, 2.0 * (1 - x * x);
  const Eigen::Vector3d l_inv_lambda = lt.inverse() * lam;
  return Eigen::Vector3d(vt * l_inv_lambda[0], vm * l_inv_lambda[1], vm * l_inv_lambda[2]);
}

const Eigen::Vector3d kApparentMass(8.0 / (3.0 * M_PI), 16.0 / (45.0 * M_PI), 16.0 / (45.0 * M_PI));

}  // namespace

Eigen::Vector3d PittPetersInflow::rates(const RotorDiskState& state, const Eigen::Vector3d& lambda) {
  const Coefficients c = coefficients(state);
  return state.rotor_speed * (c.loads - flow_term(c, lambda)).cwiseQuotient(kApparentMass);
}

Eigen::Vector3d PittPetersInflow::steady_states(const RotorDiskState& state, const Eigen::Vector3d& guess) {
  const Coefficients c = coefficients(state);
  Eigen::Vector3d lam = guess;
  if (lam[0] <= 0) lam[0] = std::sqrt(std::max(std::abs(c.loads[0]), 1e-8) / 2.0);
  // Newton iteration on the steady equations with a finite-difference Jacobian.
  for (int it = 0; it < 60; ++it) {
    const Eigen::Vector3d r = flow_term(c, lam) - c.loads;
    if (r.norm() < 1e-13) break;
    Eigen::Matrix3d jac;
    for (int j = 0; j < 3; ++j) {
      Eigen::Vector3d p = lam;
      const double h = 1e-7 * std::max(1e-3, std::abs(lam[j]));
      p[j] += h;
      jac.col(j) = (flow_term(c, p) - c.loads - r) / h;
    }
    Eigen::Vector3d step = jac.fullPivLu().solve(r);
    // damped: keep lambda_0 of the sign of the thrust
    double a = 1.0;
    while (a > 1e-3 && c.loads[0] > 0 && lam[0] - a * step[0] <= 0) a *= 0.5;
    lam -= a * step;
    if (step.norm() < 1e-12) break;
  }
  return lam;
}

void PittPetersInflow::reset(const RotorDiskState& state) {
  lambda_ = steady_states(state, Eigen::Vector3d::Zero());
  last_ = state;
}

void PittPetersInflow::advance(const RotorDiskState& state, double dt) {
  // Classical RK4 with the loads held over the step (the time constants, ~0.1 s, are far above dt).
  const Eigen::Vector3d k1 = rates(state, lambda_);
  const Eigen::Vector3d k2 = rates(state, lambda_ + 0.5 * dt * k1);
  const Eigen::Vector3d k3 = rates(state, lambda_ + 0.5 * dt * k2);
  const Eigen::Vector3d k4 = rates(state, lambda_ + dt * k3);
  lambda_ += dt / 6.0 * (k1 + 2 * k2 + 2 * k3 + k4);
  last_ = state;
}

RotorInflow PittPetersInflow::inflow() const {
  const RotorDiskState& s = last_;
  const double tip = s.rotor_speed * s.radius;
  RotorInflow in;
  // Free stream of the hub's motion, plus the induced velocity along +z (down through the disk) ...
  in.mean = -s.hub_velocity + Vec3(0, 0, lambda_[0] * tip);
  in.sine = Vec3(0, 0, lambda_[1] * tip);
  in.cosine = Vec3(0, 0, lambda_[2] * tip);
  // ... and the air's apparent motion in the rotating fuselage frame.
  add_frame_rotation(in, s.body_rate, s.radius);
  return in;
}

}  // namespace ship_lrm::rotor
