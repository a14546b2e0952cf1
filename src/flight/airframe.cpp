// Fuselage, horizontal stabiliser and fin aerodynamics (see airframe.hpp).
#include "ship_lrm/flight/airframe.hpp"

#include <cmath>

namespace ship_lrm::flight {
namespace {

// Lift coefficient of a low-aspect-ratio surface: linear up to 0.35 rad, then a flat plate
// (cl = sin 2a / 2 * peak), continuous at the joint.
double surface_cl(double slope, double a) {
  const double a_lin = 0.35;
  if (std::abs(a) <= a_lin) return slope * a;
  const double peak = slope * a_lin / std::sin(2.0 * a_lin);
  return peak * std::sin(2.0 * a);
}

}  // namespace

Airframe::Airframe(const HelicopterParameters& p)
    : fus_(p.fuselage), tp_(p.stabiliser), fn_(p.fin), vertical_drag_area_(p.fuselage.vertical_drag_area) {}

AirframeLoads Airframe::evaluate(const AirframeInputs& in) const {
  AirframeLoads out;
  // ---- fuselage: body velocity relative to the air ------------------------------------------
  const Vec3 v = in.air_velocity;
  const double speed = v.norm();
  if (speed > 1e-6) {
    const double q = 0.5 * in.density * speed * speed;
    const double alpha = std::atan2(v.z(), v.x());
    const double beta = std::asin(std::clamp(v.y() / speed, -1.0, 1.0));
    // keep the incidence polar in its attached range (reverse flight uses the mirrored value)
    const double a_eff = std::remainder(alpha, M_PI);
    const double drag = q * (fus_.drag_area + fus_.drag_area_per_rad2 * (a_eff * a_eff + beta * beta));
    const double lift = q * fus_.lift_area_per_rad * std::sin(a_eff) * std::cos(a_eff);
    const Vec3 dir = v / speed;
    out.fuselage.force = -drag * dir + lift * Vec3(std::sin(alpha), 0, -std::cos(alpha)) + Vec3(0, -q * fus_.side_area_per_rad * beta, 0);
    out.fuselage.moment = Vec3(0, q * fus_.pitch_volume_per_rad * std::sin(a_eff) * std::cos(a_eff), q * fus_.yaw_volume_per_rad * beta);
  }
  // download: vertical drag in the rotor wake (relative vertical flow of fuselage and wake)
  const double w_rel = v.z() - in.rotor_downwash.z();
  out.fuselage.force.z() += -0.5 * in.density * vertical_drag_area_ * std::abs(w_rel) * w_rel;

  // ---- lifting surfaces in the local flow -----------------------------------------------------
  const auto surface = [&](const SurfaceParameters& s, bool horizontal, const Vec3& downwash) {
    Wrench w;
    if (s.area <= 0) return w;
    // velocity of the surface relative to the air
    const Vec3 u = v + in.rate.cross(s.position) - downwash;
    const double normal = horizontal ? u.z() : u.y();
    const double sp2 = u.x() * u.x() + normal * normal;
    if (sp2 < 1e-8) return w;
    const double sp = std::sqrt(sp2);
    const double a = std::atan2(normal, u.x()) + s.incidence;
    const double cl = surface_cl(s.lift_slope, a);
    const double lift = 0.5 * in.density * sp2 * s.area * cl;
    // lift perpendicular to the local flow in the surface's plane of symmetry
    Vec3 f = Vec3::Zero();
    if (horizontal) {
      f.x() = lift * normal / sp;
      f.z() = -lift * u.x() / sp;
    } else {
      f.x() = lift * normal / sp;
      f.y() = -lift * u.x() / sp;
    }
    w.force = f;
    w.moment = s.position.cross(f);
    return w;
  };
  out.stabiliser = surface(tp_, true, tp_.downwash_factor * in.rotor_downwash / std::max(fus_.wake_factor, 1e-9));
  out.fin = surface(fn_, false, Vec3::Zero());
  return out;
}

}  // namespace ship_lrm::flight
