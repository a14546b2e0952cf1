// The LRM domain's face options of the command-line tools (see lrm_face_options.hpp).
#include "lrm_face_options.hpp"

#include <algorithm>
#include <sstream>

#include "ship_lrm/lbm/lattice.hpp"

namespace ship_lrm::tools {

namespace {

// Face set-ups of the LRM domain (issue 4, acceptances 2 and 4), applied to cfg's faces.
void apply_faces(const std::string& name, lrm::LrmConfig& cfg) {
  const lrm::LrmConfig thesis;
  cfg.faces = thesis.faces;  // velocity front, left, right; impedance back, top, bottom
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
  throw lbm::ConfigError("unknown face set-up '" + name + "' (thesis, open-sides, open, pressure, ambient or ambient-sides)");
}

const std::vector<std::string> kFaceNames = {"back", "front", "left", "right", "top", "bottom"};  // LrmConfig::faces' order

}  // namespace

void LrmFaceOptions::add_to(CLI::App& cmd) {
  cmd.add_option("--faces", faces,
                 "face set-up: thesis (velocity front/sides), open-sides, open (impedance everywhere), pressure (pressure outlets "
                 "back/top/bottom), ambient (entraining pressure faces everywhere: air leaves at the ambient pressure and enters "
                 "from rest; hover only), ambient-sides (velocity front, entraining pressure faces elsewhere)")
      ->check(CLI::IsMember({"thesis", "open-sides", "open", "pressure", "ambient", "ambient-sides"}))
      ->capture_default_str();
  cmd.add_option("--outlet-sigma", outlet_sigma,
                 "impedance faces: relaxation of their pressure to the ambient (Poinsot & Lele 1992 sigma; 0: the thesis' outlet)")
      ->check(CLI::Range(0.0, 10.0))
      ->capture_default_str();
  cmd.add_option("--relaxed-faces", relaxed_faces, "impedance faces that --outlet-sigma applies to")
      ->check(CLI::IsMember(kFaceNames))
      ->capture_default_str();
  cmd.add_flag("--rotor-far-field", far_field,
               "the faces' air includes the rotor's own induced velocity (vortex-cylinder wake of the uniformly loaded disk), "
               "which takes out most of the faces' interference");
}

std::string LrmFaceOptions::label() const {
  std::ostringstream s;
  s << faces;
  if (outlet_sigma > 0) {
    s << ";sigma=" << outlet_sigma << ":";
    for (size_t k = 0; k < relaxed_faces.size(); ++k) s << (k ? "/" : "") << relaxed_faces[k];
  }
  if (far_field) s << ";rotor-far-field";
  return s.str();
}

void LrmFaceOptions::apply(lrm::LrmConfig& cfg) const {
  apply_faces(faces, cfg);
  for (const auto& f : relaxed_faces) {
    const auto it = std::find(kFaceNames.begin(), kFaceNames.end(), f);
    if (it == kFaceNames.end()) throw lbm::ConfigError("unknown face '" + f + "' (back, front, left, right, top or bottom)");
    cfg.outlet_sigma[it - kFaceNames.begin()] = outlet_sigma;
  }
  cfg.rotor_far_field = far_field;
}

}  // namespace ship_lrm::tools
