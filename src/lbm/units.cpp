#include "ship_lrm/lbm/units.hpp"

#include <cmath>
#include <sstream>

#include "ship_lrm/lbm/lattice.hpp"

namespace ship_lrm::lbm {

UnitConverter::UnitConverter(const UnitReference& ref) : ref_(ref) {
  auto positive = [](double v, const char* what) {
    if (!(v > 0.0) || !std::isfinite(v)) throw ConfigError(std::string("unit reference: ") + what + " must be positive and finite");
  };
  positive(ref.length, "length");
  positive(ref.velocity, "velocity");
  positive(ref.viscosity, "viscosity");
  positive(ref.density, "density");
  positive(ref.lattice_velocity, "lattice velocity");
  if (ref.nodes < 3) throw ConfigError("unit reference: at least 3 nodes across the reference length");
  dx_ = ref.length / (ref.nodes - 1);
  dt_ = ref.lattice_velocity * dx_ / ref.velocity;
  if (mach_number() > kMaxSetupMach) {
    std::ostringstream s;
    s << "unit reference: lattice velocity " << ref.lattice_velocity << " is Mach " << mach_number() << " > limit " << kMaxSetupMach;
    throw ConfigError(s.str());
  }
}

double UnitConverter::mach_number() const { return ref_.lattice_velocity * std::sqrt(3.0); }

}  // namespace ship_lrm::lbm
