// Pilot controls (% of travel) <-> blade pitch (see controls.hpp).
#include "ship_lrm/flight/controls.hpp"

#include <cmath>
#include <string>

namespace ship_lrm::flight {
namespace {
void check(double v, const char* name) {
  if (!std::isfinite(v) || v < 0.0 || v > 100.0)
    throw ControlError(std::string("control '") + name + "' = " + std::to_string(v) + " % is outside 0..100 %");
}
}  // namespace

BladeAngles map_controls(const PilotControls& c, const ControlParameters& p, bool right_pedal_increases_tail_pitch) {
  check(c.collective, "collective");
  check(c.longitudinal, "longitudinal");
  check(c.lateral, "lateral");
  check(c.pedal, "pedal");
  BladeAngles a;
  a.main.collective = p.collective_min + c.collective / 100.0 * (p.collective_max - p.collective_min);
  a.main.forward = (c.longitudinal - 50.0) / 50.0 * p.longitudinal;
  a.main.right = (c.lateral - 50.0) / 50.0 * p.lateral;
  const double pedal = right_pedal_increases_tail_pitch ? c.pedal : 100.0 - c.pedal;
  a.tail = p.tail_min + pedal / 100.0 * (p.tail_max - p.tail_min);
  return a;
}

PilotControls unmap_controls(const BladeAngles& a, const ControlParameters& p, bool right_pedal_increases_tail_pitch) {
  PilotControls c;
  c.collective = (a.main.collective - p.collective_min) / (p.collective_max - p.collective_min) * 100.0;
  c.longitudinal = 50.0 + a.main.forward / p.longitudinal * 50.0;
  c.lateral = 50.0 + a.main.right / p.lateral * 50.0;
  const double pedal = (a.tail - p.tail_min) / (p.tail_max - p.tail_min) * 100.0;
  c.pedal = right_pedal_increases_tail_pitch ? pedal : 100.0 - pedal;
  return c;
}

}  // namespace ship_lrm::flight
