// Evaluation of the inflow and force harmonics of the rotor interface (thesis 6.5).
#include "ship_lrm/rotor/inflow_model.hpp"

#include <cmath>

namespace ship_lrm::rotor {

Vec3 RotorInflow::at(double r_over_R, double psi) const {
  return mean + sine * (r_over_R * std::sin(psi)) + cosine * (r_over_R * std::cos(psi));
}

Vec3 RotorForceHarmonics::at(double psi) const {
  Vec3 f = cos[0];
  for (int k = 1; k <= kHarmonicOrder; ++k) f += cos[k] * std::cos(k * psi) + sin[k] * std::sin(k * psi);
  return f;
}

void add_frame_rotation(RotorInflow& in, const Vec3& body_rate, double radius) {
  in.cosine += radius * body_rate.cross(Vec3::UnitX());
  in.sine -= radius * body_rate.cross(Vec3::UnitY());
}

}  // namespace ship_lrm::rotor
