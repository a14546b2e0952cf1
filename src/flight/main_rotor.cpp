// Main rotor blade dynamics, blade-element aerodynamics and hub loads (equations in main_rotor.hpp).
#include "ship_lrm/flight/main_rotor.hpp"

#include <algorithm>
#include <cmath>

namespace ship_lrm::flight {
namespace {

inline Vec3 e_r(double a) { return {-std::cos(a), std::sin(a), 0.0}; }
inline Vec3 e_t(double a) { return {std::sin(a), std::cos(a), 0.0}; }
const Vec3 kZ = Vec3::UnitZ();

}  // namespace

MainRotor::MainRotor(const HelicopterParameters& params) : record_(params.main_rotor.blades) {
  const auto& p = params.main_rotor;
  clockwise_ = p.clockwise;
  nblades_ = p.blades;
  radius_ = p.radius;
  chord_ = p.chord;
  twist_ = p.twist;
  twist_ref_ = p.twist_reference;
  hinge_ = p.hinge_offset;
  const double len = radius_ - hinge_;
  // Uniform blade from the hinge to the tip with the configured flap inertia about the rotor centre.
  mass_ = 3.0 * p.blade_flap_inertia * len / (std::pow(radius_, 3) - std::pow(hinge_, 3));
  first_moment_ = mass_ * len / 2.0;
  inertia_ = mass_ * len * len / 3.0;
  const double om2 = p.rotor_speed * p.rotor_speed;
  k_flap_ = inertia_ * om2 * (p.flap_frequency_ratio * p.flap_frequency_ratio - 1.0 - hinge_ * first_moment_ / inertia_);
  if (k_flap_ < 0)
    throw ParameterError(params.source + ": field 'main_rotor.hinge_offset' is too large for 'main_rotor.flap_frequency_ratio' (" +
                         "the hinge alone gives a higher flap frequency)");
  k_lag_ = inertia_ * om2 * p.lag_frequency_ratio * p.lag_frequency_ratio - hinge_ * first_moment_ * om2;
  if (k_lag_ < 0)
    throw ParameterError(params.source + ": field 'main_rotor.hinge_offset' is too large for 'main_rotor.lag_frequency_ratio'");
  c_lag_ = 2.0 * p.lag_damping_ratio * inertia_ * p.lag_frequency_ratio * p.rotor_speed;
  for (size_t i = 0; i + 1 < p.stations.size(); ++i) {
    Element e;
    e.r_over_R = 0.5 * (p.stations[i] + p.stations[i + 1]);
    e.dr = (p.stations[i + 1] - p.stations[i]) * radius_;
    e.s = e.r_over_R * radius_ - hinge_;
    // tip loss (Prandtl/Wheatley factor B): no lift outboard of B R
    e.lift_fraction = std::clamp((p.tip_loss - p.stations[i]) / (p.stations[i + 1] - p.stations[i]), 0.0, 1.0);
    elements_.push_back(e);
  }
  polar_storage_ = p.polar;
  polar_ = &polar_storage_;
  blades_.assign(nblades_, BladeState{});
}

double MainRotor::geometric_azimuth(int blade) const {
  const double a = azimuth_ + 2.0 * M_PI * blade / nblades_;
  return clockwise_ ? -a : a;
}

Vec3 MainRotor::multiblade_flap() const {
  double a0 = 0, fwd = 0, right = 0;
  for (int i = 0; i < nblades_; ++i) {
    const double psi = geometric_azimuth(i);
    const double b = blades_[i].flap;
    a0 += b / nblades_;
    // flap up at the rear (psi = 0) tilts the disk forward; flap up at port (psi = 270) tilts it to starboard
    fwd += 2.0 / nblades_ * b * std::cos(psi);
    right += -2.0 / nblades_ * b * std::sin(psi);
  }
  return {a0, fwd, right};
}

MainRotor::BladeResult MainRotor::blade(const MainRotorInputs& in, const Vec3& w, const Vec3& wdot, const Vec3& ahub, double psi,
                                        const BladeState& b, double theta0, double fwd, double right) const {
  const double om = in.rotor_speed, omdot = in.rotor_acceleration;
  const double phi = psi - b.lag;
  const double cb = std::cos(b.flap), sb = std::sin(b.flap);
  const Vec3 erp = e_r(psi), etp = e_t(psi), erf = e_r(phi), etf = e_t(phi);
  const Vec3 bhat = cb * erf - sb * kZ;
  const Vec3 nhat = -sb * erf - cb * kZ;
  const Vec3& that = etf;
  const double phidot = om - b.lag_rate;
  const Vec3 bdot = -sb * b.flap_rate * erf + cb * phidot * etf - cb * b.flap_rate * kZ;
  const Vec3 bddot0 = -cb * (b.flap_rate * b.flap_rate + phidot * phidot) * erf + (-2.0 * sb * b.flap_rate * phidot + cb * omdot) * etf +
                      sb * b.flap_rate * b.flap_rate * kZ;
  const Vec3 p0 = hinge_ * erp;
  const Vec3 v0 = hinge_ * om * etp;
  const Vec3 arel0 = hinge_ * (omdot * etp - om * om * erp);
  const Vec3 acc_a = ahub + wdot.cross(p0) + w.cross(w.cross(p0)) + 2.0 * w.cross(v0) + arel0;
  const Vec3 acc_b = wdot.cross(bhat) + w.cross(w.cross(bhat)) + 2.0 * w.cross(bdot) + bddot0;

  BladeResult r{};
  r.aero_force.setZero();
  r.aero_moment.setZero();
  double q_flap = 0, q_lag = 0;
  if (in.aerodynamics) {
    const double sp = std::sin(psi), cp = std::cos(psi);
    // inflow in the computation frame at this blade's azimuth (mirror for a clockwise rotor)
    const double sgeo = clockwise_ ? -sp : sp;
    Vec3 mean = in.inflow.mean, sine = in.inflow.sine, cosine = in.inflow.cosine;
    if (clockwise_) {
      mean.y() = -mean.y();
      sine.y() = -sine.y();
      cosine.y() = -cosine.y();
    }
    const double theta_cyc = theta0 - fwd * sp - right * cp;
    const double half_rho_c = 0.5 * in.density * chord_;
    for (const Element& e : elements_) {
      const Vec3 pos = p0 + e.s * bhat;
      const Vec3 vrel = v0 + e.s * bdot;
      const Vec3 air = mean + sine * (e.r_over_R * sgeo) + cosine * (e.r_over_R * cp);
      const Vec3 u = air - vrel;
      const double ut = -u.dot(that), up = -u.dot(nhat);
      const double umag = std::sqrt(ut * ut + up * up);
      if (umag < 1e-9) continue;
      const double theta = theta_cyc + twist_ * (e.r_over_R - twist_ref_);
      const double alpha = theta - std::atan2(up, ut);
      const SectionCoefficients c = polar_->lookup(alpha, umag / in.speed_of_sound);
      const double k = half_rho_c * e.dr * umag;
      const double cl = c.cl * e.lift_fraction;
      const Vec3 df = k * ((cl * -up - c.cd * ut) * that + (cl * ut - c.cd * up) * nhat);
      q_flap += e.s * nhat.dot(df);
      q_lag -= e.s * cb * that.dot(df);
      r.aero_force += df;
      r.aero_moment += pos.cross(df);
      r.pitch_moment += half_rho_c * chord_ * e.dr * umag * umag * c.cm;
    }
  }
  r.flap_acc = (q_flap - k_flap_ * b.flap - (first_moment_ * nhat.dot(acc_a) + inertia_ * nhat.dot(acc_b))) / inertia_;
  r.lag_acc = (q_lag - k_lag_ * b.lag - c_lag_ * b.lag_rate + cb * (first_moment_ * that.dot(acc_a) + inertia_ * that.dot(acc_b))) /
              (inertia_ * cb * cb);
  // Loads passed to the hub: aerodynamic minus the blade's inertia in its motion relative to the
  // fuselage (relative + Coriolis); the rigid-body part is in the aircraft's mass and inertia.
  // Linearisation in x = (hub specific force, body angular acceleration): see the header.
  r.flap_gain.head<3>() = -first_moment_ / inertia_ * nhat;
  r.flap_gain.tail<3>() = -(first_moment_ * p0.cross(nhat) + inertia_ * bhat.cross(nhat)) / inertia_;
  r.lag_gain.head<3>() = first_moment_ / (inertia_ * cb) * that;
  r.lag_gain.tail<3>() = (first_moment_ * p0.cross(that) + inertia_ * bhat.cross(that)) / (inertia_ * cb);
  r.nhat = nhat;
  r.that_cb = cb * that;
  r.lever = first_moment_ * p0 + inertia_ * bhat;
  const Vec3 atr_a = 2.0 * w.cross(v0) + arel0;
  const Vec3 atr_b = 2.0 * w.cross(bdot) + bddot0 + r.flap_acc * nhat - r.lag_acc * cb * that;
  r.force = r.aero_force - (mass_ * atr_a + first_moment_ * atr_b);
  r.moment =
      r.aero_moment - (mass_ * p0.cross(atr_a) + first_moment_ * (p0.cross(atr_b) + bhat.cross(atr_a)) + inertia_ * bhat.cross(atr_b));
  return r;
}

namespace {
// mr -> computation frame (identity for a counterclockwise rotor, mirror y -> -y for a clockwise one).
inline Vec3 polar_to_c(const Vec3& v, bool cw) { return cw ? Vec3(v.x(), -v.y(), v.z()) : v; }
inline Vec3 axial_to_c(const Vec3& v, bool cw) { return cw ? Vec3(-v.x(), v.y(), -v.z()) : v; }
}  // namespace

MainRotorLoads MainRotor::evaluate(const MainRotorInputs& in) const {
  const Vec3 w = axial_to_c(in.body_rate, clockwise_), wdot = axial_to_c(in.body_angular_acceleration, clockwise_);
  const Vec3 ahub = polar_to_c(in.hub_specific_force, clockwise_);
  const double right = clockwise_ ? -in.pitch.right : in.pitch.right;
  Vec3 f = Vec3::Zero(), m = Vec3::Zero(), fa = Vec3::Zero(), ma = Vec3::Zero();
  double pitch_moment = 0;
  for (int i = 0; i < nblades_; ++i) {
    const double psi = azimuth_ + 2.0 * M_PI * i / nblades_;
    const BladeResult r = blade(in, w, wdot, ahub, psi, blades_[i], in.pitch.collective, in.pitch.forward, right);
    f += r.force;
    m += r.moment;
    fa += r.aero_force;
    ma += r.aero_moment;
    pitch_moment += r.pitch_moment;
  }
  return to_mr(f, m, fa, ma, pitch_moment, 1.0);
}

MainRotorLoads MainRotor::step(const MainRotorInputs& in, double dt, int substeps, const RotorCoupling* coupling) {
  const Vec3 w = axial_to_c(in.body_rate, clockwise_);
  const double right = clockwise_ ? -in.pitch.right : in.pitch.right;
  const double h = dt / substeps;
  // mirror of the 6-vectors (force-like, moment-like) between mr and the computation frame
  Vec6 mirror = Vec6::Ones();
  if (clockwise_) mirror << 1, -1, 1, -1, 1, -1;
  Vec3 f = Vec3::Zero(), m = Vec3::Zero(), fa = Vec3::Zero(), ma = Vec3::Zero();
  double pitch_moment = 0;
  std::vector<BladeResult>& res = scratch_;
  res.resize(nblades_);
  for (int sub = 0; sub < substeps; ++sub) {
    // blade accelerations and hub loads at x = 0, and their dependence on x
    Vec6 w0 = Vec6::Zero();
    Mat6 k = Mat6::Zero();
    for (int i = 0; i < nblades_; ++i) {
      const double psi = azimuth_ + 2.0 * M_PI * i / nblades_;
      res[i] = blade(in, w, Vec3::Zero(), Vec3::Zero(), psi, blades_[i], in.pitch.collective, in.pitch.forward, right);
      const BladeResult& r = res[i];
      w0.head<3>() += r.force;
      w0.tail<3>() += r.moment;
      // u = flap_acc n - lag_acc cb t;  dF = -S du,  dM = -lever x du
      Eigen::Matrix<double, 3, 6> du = r.nhat * r.flap_gain.transpose() - r.that_cb * r.lag_gain.transpose();
      k.topRows<3>() += -first_moment_ * du;
      for (int j = 0; j < 6; ++j) k.block<3, 1>(3, j) += -r.lever.cross(Vec3(du.col(j)));
    }
    Vec6 x_c;
    if (coupling) {
      const Vec6 w0_mr = mirror.cwiseProduct(w0);
      const Mat6 k_mr = mirror.asDiagonal() * k * mirror.asDiagonal();
      x_c = mirror.cwiseProduct((*coupling)(w0_mr, k_mr));
    } else {
      x_c.head<3>() = polar_to_c(in.hub_specific_force, clockwise_);
      x_c.tail<3>() = axial_to_c(in.body_angular_acceleration, clockwise_);
    }
    const Vec6 wx = w0 + k * x_c;
    f += wx.head<3>();
    m += wx.tail<3>();
    for (int i = 0; i < nblades_; ++i) {
      const double psi = azimuth_ + 2.0 * M_PI * i / nblades_;
      BladeState& b = blades_[i];
      const BladeResult& r = res[i];
      const double flap_acc = r.flap_acc + r.flap_gain.dot(x_c);
      const double lag_acc = r.lag_acc + r.lag_gain.dot(x_c);
      fa += r.aero_force;
      ma += r.aero_moment;
      pitch_moment += r.pitch_moment;
      record_.deposit(i, clockwise_ ? -psi : psi, polar_to_c(r.aero_force, clockwise_));
      // semi-implicit (symplectic) Euler: rates first, then angles with the new rates
      b.flap_rate += h * flap_acc;
      b.lag_rate += h * lag_acc;
      b.flap += h * b.flap_rate;
      b.lag += h * b.lag_rate;
      if (!std::isfinite(b.flap) || !std::isfinite(b.lag))
        throw std::runtime_error("main rotor: blade motion diverged (non-finite flap or lag); reduce the time step or add blade_substeps");
    }
    azimuth_ = std::remainder(azimuth_ + h * in.rotor_speed, 2.0 * M_PI);
  }
  return to_mr(f, m, fa, ma, pitch_moment, 1.0 / substeps);
}

MainRotorLoads MainRotor::to_mr(const Vec3& f, const Vec3& m, const Vec3& fa, const Vec3& ma, double pitch_moment, double scale) const {
  MainRotorLoads l;
  l.aero_torque = ma.z() * scale;
  l.force = polar_to_c(f * scale, clockwise_);
  l.moment = axial_to_c(m * scale, clockwise_);
  l.aero_force = polar_to_c(fa * scale, clockwise_);
  l.aero_moment = axial_to_c(ma * scale, clockwise_);
  l.blade_pitch_moment = pitch_moment * scale;
  return l;
}

}  // namespace ship_lrm::flight
