// Pitt-Peters three-state dynamic inflow (Pitt & Peters 1981, Vertica 5; with the mass-flow
// parameter of Peters & HaQuang 1988, JAHS 33(4)):
//   M d(lambda)/d(Omega t) + V Ltilde^-1 lambda = (C_T, C_s, C_c)
// lambda = (lambda_0, lambda_s, lambda_c): induced velocity / (Omega R), positive down through the disk,
// v_i(r, psi) = Omega R (lambda_0 + lambda_s (r/R) sin psi + lambda_c (r/R) cos psi) with psi of
// inflow_model.hpp. C_s and C_c are the moment coefficients of starboard and aft loading (they drive
// lambda_s and lambda_c with a positive sign):
//   C_T = T / (rho A (Omega R)^2),  C_s = -M_x / (rho A (Omega R)^2 R),  C_c = -M_y / (rho A (Omega R)^2 R)
//   M = diag(8/(3 pi), 16/(45 pi), 16/(45 pi))
//   Ltilde = [[1/2, 0, -15 pi/64 X], [0, 2 (1 + X^2), 0], [15 pi/64 X, 0, 2 (1 - X^2)]], X = tan(chi/2)
//     (Ltilde_22 = 4/(1 + cos chi), Ltilde_33 = 4 cos chi/(1 + cos chi) of Pitt & Peters; their rows 2
//     and 3 are written for the aerodynamic roll and pitch moments, -C_s and -C_c here, which flips
//     the sign of Ltilde_13 in this convention: thrust raises the inflow at the rear (lambda_c > 0)
//     and the 1-3 block stays regular at every skew angle)
//   V = diag(V_T, V_m, V_m), V_T = sqrt(mu^2 + lambda^2), V_m = (mu^2 + lambda (lambda + lambda_0)) / V_T
//   lambda = lambda_0 + lambda_free (total inflow ratio), chi = atan(mu / lambda) the wake skew angle.
// In hover the steady lambda_0 = sqrt(C_T / 2): momentum theory.
#pragma once

#include <Eigen/Core>

#include "ship_lrm/rotor/inflow_model.hpp"

namespace ship_lrm::rotor {

class PittPetersInflow final : public InflowModel {
 public:
  std::string name() const override { return "pitt_peters"; }
  void reset(const RotorDiskState& state) override;
  void advance(const RotorDiskState& state, double dt) override;
  RotorInflow inflow() const override;

  // Induced states (lambda_0, lambda_s, lambda_c), nondimensional.
  const Eigen::Vector3d& states() const { return lambda_; }
  // Steady states for this rotor state (what advance() converges to at constant loads).
  static Eigen::Vector3d steady_states(const RotorDiskState& state, const Eigen::Vector3d& guess);
  // d(lambda)/dt in 1/s for the given states.
  static Eigen::Vector3d rates(const RotorDiskState& state, const Eigen::Vector3d& lambda);

 private:
  Eigen::Vector3d lambda_ = Eigen::Vector3d::Zero();
  RotorDiskState last_;
};

}  // namespace ship_lrm::rotor
