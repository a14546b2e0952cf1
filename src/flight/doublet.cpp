// Doublet manoeuvre from trim (see doublet.hpp).
#include "ship_lrm/flight/doublet.hpp"

#include <cmath>
#include <stdexcept>

namespace ship_lrm::flight {

ControlAxis parse_control_axis(const std::string& n) {
  if (n == "collective") return ControlAxis::Collective;
  if (n == "longitudinal") return ControlAxis::Longitudinal;
  if (n == "lateral") return ControlAxis::Lateral;
  if (n == "pedal") return ControlAxis::Pedal;
  throw std::invalid_argument("unknown control axis '" + n + "' (collective, longitudinal, lateral or pedal)");
}

std::string to_string(ControlAxis a) {
  switch (a) {
    case ControlAxis::Collective:
      return "collective";
    case ControlAxis::Longitudinal:
      return "longitudinal";
    case ControlAxis::Lateral:
      return "lateral";
    case ControlAxis::Pedal:
      return "pedal";
  }
  return "?";
}

DoubletResult run_doublet(const HelicopterParameters& params, const DoubletOptions& opt) {
  if (!(opt.amplitude > 0 && opt.amplitude <= 50)) throw std::invalid_argument("doublet amplitude must lie in (0, 50] % of travel");
  if (!(opt.pulse > 0) || !(opt.start >= 0) || !(opt.duration > opt.start))
    throw std::invalid_argument("doublet needs pulse > 0 and duration > start >= 0");
  if (!(opt.speed >= 0 && opt.speed <= 90)) throw std::invalid_argument("doublet speed must lie in 0..90 m/s");
  Helicopter heli(params, nullptr, opt.engine);
  DoubletResult out;
  TrimTarget target;
  target.speed = opt.speed;
  out.trim = trim(heli, target);
  if (!out.trim.converged) throw std::runtime_error(out.trim.message);
  const PilotControls trimmed = out.trim.controls;
  const double dt = params.time_step;
  const int every = std::max(1, static_cast<int>(std::lround(opt.sample_interval / dt)));
  const int steps = static_cast<int>(std::ceil(opt.duration / dt));
  for (int i = 0; i <= steps; ++i) {
    const double t = i * dt;
    PilotControls c = trimmed;
    double delta = 0;
    if (t >= opt.start && t < opt.start + opt.pulse)
      delta = opt.amplitude;
    else if (t >= opt.start + opt.pulse && t < opt.start + 2 * opt.pulse)
      delta = -opt.amplitude;
    double* axis = opt.axis == ControlAxis::Collective     ? &c.collective
                   : opt.axis == ControlAxis::Longitudinal ? &c.longitudinal
                   : opt.axis == ControlAxis::Lateral      ? &c.lateral
                                                           : &c.pedal;
    *axis = std::clamp(*axis + delta, 0.0, 100.0);
    heli.set_controls(c);
    if (i % every == 0) {
      const auto& b = heli.body();
      DoubletSample s;
      s.time = t;
      s.controls = c;
      s.rates = b.rate;
      s.attitude = b.euler();
      s.rate_of_descent = (b.attitude * b.velocity).z();
      s.rotor_speed_ratio = heli.engine_state().rotor_speed / heli.engine().reference_speed();
      s.main_power = heli.outputs().main_power;
      s.engine_power = heli.outputs().engine_power;
      out.samples.push_back(s);
    }
    if (i < steps) heli.step();
  }
  return out;
}

}  // namespace ship_lrm::flight
