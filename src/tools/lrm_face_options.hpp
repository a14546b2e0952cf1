// The LRM domain's face and lattice options of the command-line tools (`sweep inflow`, `sweep ground`, `trim
// --inflow lrm`): the set-up of the six faces, the impedance faces' relaxation to the ambient
// pressure, the rotor's own far field in the faces' air, the collision and its Smagorinsky constant
// (lrm::LrmConfig).
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "ship_lrm/lrm/domain.hpp"

namespace ship_lrm::tools {

struct LrmFaceOptions {
  std::string faces = "thesis";
  double outlet_sigma = 0.0;
  std::vector<std::string> relaxed_faces = {"back", "top", "bottom"};
  bool far_field = false;
  std::string collision = "bgk";
  bool characteristic_inlets = false;
  int absorbing_layer = 0;
  double smagorinsky = lrm::LrmConfig{}.smagorinsky;  // thesis 6.1

  // --faces, --outlet-sigma, --relaxed-faces, --rotor-far-field, --collision, --characteristic-inlets,
  // --absorbing-layer, --smagorinsky
  void add_to(CLI::App& cmd);
  // The faces column of the CSVs: the set-up, the relaxed outlets when there are any, the far field.
  std::string label() const;
  // Sets cfg's faces, outlet relaxation, far field, collision and Smagorinsky constant; ConfigError
  // for an unknown set-up.
  void apply(lrm::LrmConfig& cfg) const;
};

// A command whose inflow model is not the LRM: an LRM-only option given to it (one of `others` or the
// face options) would be ignored without a word, so it is refused (CLI::ValidationError naming it).
void refuse_lrm_options(const CLI::App& cmd, std::initializer_list<const char*> others);

}  // namespace ship_lrm::tools
