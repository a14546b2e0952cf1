// Analytic actuator-disk references (Glauert; e.g. Johnson, Rotorcraft Aeromechanics, 2013, ch. 4-5).
#pragma once

#include <cmath>

namespace ship_lrm::rotor {

// Hover induced velocity v_h = sqrt(T / (2 rho A)).
inline double hover_induced_velocity(double thrust, double density, double radius) {
  return std::sqrt(thrust / (2.0 * density * M_PI * radius * radius));
}

// Glauert's forward-flight induced velocity of a disk at zero incidence in an edgewise stream V:
// v = T / (2 rho A sqrt(V^2 + v^2)), solved by Newton iteration.
inline double glauert_induced_velocity(double thrust, double density, double radius, double speed) {
  const double vh2 = thrust / (2.0 * density * M_PI * radius * radius);
  double v = std::sqrt(vh2);
  for (int i = 0; i < 50; ++i) {
    // f(v) = v sqrt(V^2 + v^2) - vh^2
    const double s = std::sqrt(speed * speed + v * v);
    const double f = v * s - vh2;
    const double df = s + v * v / s;
    const double dv = f / df;
    v -= dv;
    if (std::abs(dv) < 1e-12 * (1 + v)) break;
  }
  return v;
}

// Ideal induced power of hover, T v_h.
inline double hover_ideal_power(double thrust, double density, double radius) {
  return thrust * hover_induced_velocity(thrust, density, radius);
}

}  // namespace ship_lrm::rotor
