// Analytic actuator-disk references (Glauert; e.g. Johnson, Rotorcraft Aeromechanics, 2013, ch. 4-5).
#pragma once

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ship_lrm::rotor {

// Hover induced velocity v_h = sqrt(T / (2 rho A)).
inline double hover_induced_velocity(double thrust, double density, double radius) {
  return std::sqrt(thrust / (2.0 * density * M_PI * radius * radius));
}

// Glauert's induced velocity with the wake carried by the air relative to the disk plus the induced
// velocity itself: v sqrt(V_inplane^2 + (V_normal + v)^2) = v_h^2, with V_normal the air's velocity
// relative to the disk along the induced flow (the mr frame's z, down: positive when the air passes
// the disk downwards, as in a climb) and v > 0 along it. Newton from the larger of v_h and the
// edgewise estimate; throws std::invalid_argument when it finds no positive root (the vortex-ring
// state of a descent).
inline double momentum_induced_velocity(double thrust, double density, double radius, double inplane_speed, double normal_velocity) {
  const double vh2 = thrust / (2.0 * density * M_PI * radius * radius);
  const double inplane2 = inplane_speed * inplane_speed;
  double v = std::max(std::sqrt(vh2), vh2 / std::sqrt(inplane2 + 1e-300));
  v = std::min(v, std::sqrt(vh2) * 1e3);
  for (int i = 0; i < 100; ++i) {
    const double w = normal_velocity + v, s = std::sqrt(inplane2 + w * w);
    const double f = v * s - vh2, df = s + v * w / s;
    if (!(df > 0)) break;
    const double dv = f / df;
    v -= dv;
    if (std::abs(dv) < 1e-12 * (1.0 + std::abs(v))) {
      if (v > 0) return v;
      break;
    }
  }
  throw std::invalid_argument("momentum theory found no induced velocity for this descent (vortex-ring state)");
}

// Glauert's forward-flight induced velocity of a disk at zero incidence in an edgewise stream V:
// v = T / (2 rho A sqrt(V^2 + v^2)).
inline double glauert_induced_velocity(double thrust, double density, double radius, double speed) {
  return momentum_induced_velocity(thrust, density, radius, speed, 0.0);
}

// Ideal induced power of hover, T v_h.
inline double hover_ideal_power(double thrust, double density, double radius) {
  return thrust * hover_induced_velocity(thrust, density, radius);
}

}  // namespace ship_lrm::rotor
