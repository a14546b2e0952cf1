// Airframe aerodynamics: fuselage polar over incidence and sideslip (thesis 6.6 uses an incidence-
// only polar; sideslip terms added here), rotor-wake download on the fuselage, horizontal
// stabiliser and fin as lifting surfaces in the local flow (Padfield 2nd ed., 3.2.3-3.2.5).
#pragma once

#include "ship_lrm/flight/parameters.hpp"
#include "ship_lrm/flight/rigid_body.hpp"

namespace ship_lrm::flight {

struct AirframeInputs {
  Vec3 air_velocity = Vec3::Zero();    // velocity of the aircraft's cg relative to the air, body axes
  Vec3 rate = Vec3::Zero();            // body rates
  Vec3 rotor_downwash = Vec3::Zero();  // main-rotor wake velocity at the airframe, body axes (down is +z)
  double density = 1.225;
};

struct AirframeLoads {
  Wrench fuselage, stabiliser, fin;
  Wrench total() const {
    Wrench w = fuselage;
    w += stabiliser;
    w += fin;
    return w;
  }
};

class Airframe {
 public:
  explicit Airframe(const HelicopterParameters& p);
  AirframeLoads evaluate(const AirframeInputs& in) const;

 private:
  FuselageParameters fus_;
  SurfaceParameters tp_, fn_;
  double vertical_drag_area_;
};

}  // namespace ship_lrm::flight
