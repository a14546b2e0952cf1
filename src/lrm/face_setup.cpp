// Named set-ups of the LRM domain's faces (see face_setup.hpp).
#include "ship_lrm/lrm/face_setup.hpp"

#include <algorithm>
#include <cmath>

#include "ship_lrm/lbm/lattice.hpp"

namespace ship_lrm::lrm {

namespace {
// "a, b, ... or z": the choices for an error message
std::string choices(const std::vector<std::string>& names) {
  std::string s;
  for (std::size_t i = 0; i < names.size(); ++i) s += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
  return s;
}
}  // namespace

const std::vector<std::string>& face_setup_names() {
  static const std::vector<std::string> names = {"thesis", "open-sides", "open", "pressure", "ambient", "ambient-sides"};
  return names;
}

const std::vector<std::string>& face_names() {
  static const std::vector<std::string> names = {"back", "front", "left", "right", "top", "bottom"};
  return names;
}

void apply_face_setup(const std::string& name, LrmConfig& cfg) {
  const LrmConfig thesis;
  cfg.faces = thesis.faces;  // velocity front, left, right; impedance back, top, bottom (thesis 6.4)
  cfg.entraining_pressure_faces = false;
  if (name == "thesis") return;
  if (name == "open") {  // impedance on all six (the author's earlier set-up, thesis 8.2.3)
    cfg.faces.fill(lbm::FaceType::ImpedanceOutlet);
    return;
  }
  if (name == "open-sides") {  // velocity front only: the wall jet may leave sideways
    cfg.faces[2] = cfg.faces[3] = lbm::FaceType::ImpedanceOutlet;
    return;
  }
  if (name == "pressure") {  // velocity front and sides; pressure outlets (ambient density) back, top, bottom
    for (int f : {0, 4, 5}) cfg.faces[f] = lbm::FaceType::PressureOutlet;
    return;
  }
  if (name == "ambient" || name == "ambient-sides") {
    // entraining pressure faces (LrmConfig::entraining_pressure_faces) on all six faces, or on all
    // but the front, which stays a velocity face and holds the stream
    cfg.faces.fill(lbm::FaceType::PressureOutlet);
    if (name == "ambient-sides") cfg.faces[1] = lbm::FaceType::VelocityInlet;
    cfg.entraining_pressure_faces = true;
    return;
  }
  throw ConfigError("unknown face set-up '" + name + "' (" + choices(face_setup_names()) + ")");
}

void relax_faces(const std::vector<std::string>& faces, double sigma, LrmConfig& cfg) {
  if (!(sigma >= 0 && sigma <= 10)) throw ConfigError("the outlets' relaxation sigma must lie in [0, 10], not " + std::to_string(sigma));
  const auto& names = face_names();
  for (const auto& f : faces) {
    const auto it = std::find(names.begin(), names.end(), f);
    if (it == names.end()) throw ConfigError("unknown face '" + f + "' (" + choices(names) + ")");
    cfg.outlet_sigma[it - names.begin()] = sigma;
  }
}

}  // namespace ship_lrm::lrm
