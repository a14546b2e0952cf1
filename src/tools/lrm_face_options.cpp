// The LRM domain's face and lattice options of the command-line tools (see lrm_face_options.hpp).
#include "lrm_face_options.hpp"

#include <sstream>

#include "ship_lrm/lrm/face_setup.hpp"

namespace ship_lrm::tools {

void LrmFaceOptions::add_to(CLI::App& cmd) {
  cmd.add_option("--faces", faces,
                 "face set-up: thesis (velocity front/sides), open-sides, open (impedance everywhere), pressure (pressure outlets "
                 "back/top/bottom), ambient (entraining pressure faces everywhere: air leaves at the ambient pressure and enters "
                 "from rest; hover only), ambient-sides (velocity front, entraining pressure faces elsewhere)")
      ->check(CLI::IsMember(lrm::face_setup_names()))
      ->capture_default_str();
  cmd.add_option("--outlet-sigma", outlet_sigma,
                 "impedance faces: relaxation of their pressure to the ambient (Poinsot & Lele 1992 sigma; 0: the thesis' outlet)")
      ->check(CLI::Range(0.0, 10.0))
      ->capture_default_str();
  cmd.add_option("--relaxed-faces", relaxed_faces, "impedance faces that --outlet-sigma applies to")
      ->check(CLI::IsMember(lrm::face_names()))
      ->capture_default_str();
  cmd.add_flag("--rotor-far-field", far_field,
               "the faces' air includes the rotor's own induced velocity (vortex-cylinder wake of the uniformly loaded disk), "
               "which takes out most of the faces' interference");
  cmd.add_option("--collision", collision,
                 "LBM collision: bgk (the thesis') or recursive (recursive regularised, Coreixas et al. 2017: stable at the "
                 "LRM's lattice Mach number 0.3, where BGK's stream grows noise)")
      ->check(CLI::IsMember({"bgk", "recursive"}))
      ->capture_default_str();
  cmd.add_flag("--characteristic-inlets", characteristic_inlets,
               "velocity faces let outgoing waves leave instead of reflecting them (non-reflecting inlets)");
  cmd.add_option("--absorbing-layer", absorbing_layer,
                 "velocity faces: an absorbing layer of this many cells that pulls the air towards the face's (0: none); "
                 "damps the grid-scale mode where the inflow face meets a moving ground")
      ->check(CLI::Range(0, 16))
      ->capture_default_str();
  cmd.add_option("--smagorinsky", smagorinsky,
                 "Smagorinsky constant s of the LRM's subgrid viscosity (thesis 6.1: 0.05; 0: none, which at the LRM's lattice "
                 "Mach number lets BGK's stream grow noise)")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
}

void refuse_lrm_options(const CLI::App& cmd, std::initializer_list<const char*> others) {
  const auto refuse = [&](const char* name) {
    if (cmd.get_option(name)->count() > 0) throw CLI::ValidationError(name, "applies to the LRM only: add --inflow lrm");
  };
  for (const char* name : others) refuse(name);
  for (const char* name : {"--faces", "--outlet-sigma", "--relaxed-faces", "--rotor-far-field", "--collision", "--characteristic-inlets",
                           "--absorbing-layer", "--smagorinsky"})
    refuse(name);
}

std::string LrmFaceOptions::label() const {
  std::ostringstream s;
  s << faces;
  if (outlet_sigma > 0) {
    s << ";sigma=" << outlet_sigma << ":";
    for (size_t k = 0; k < relaxed_faces.size(); ++k) s << (k ? "/" : "") << relaxed_faces[k];
  }
  if (far_field) s << ";rotor-far-field";
  if (collision != "bgk") s << ";" << collision;
  if (characteristic_inlets) s << ";characteristic-inlets";
  if (absorbing_layer > 0) s << ";absorbing-layer=" << absorbing_layer;
  if (smagorinsky != lrm::LrmConfig{}.smagorinsky) s << ";smagorinsky=" << smagorinsky;
  return s.str();
}

void LrmFaceOptions::apply(lrm::LrmConfig& cfg) const {
  lrm::apply_face_setup(faces, cfg);
  lrm::relax_faces(relaxed_faces, outlet_sigma, cfg);
  cfg.rotor_far_field = far_field;
  cfg.collision = lbm::parse_collision_model(collision);
  cfg.characteristic_inlets = characteristic_inlets;
  cfg.absorbing_layer = absorbing_layer;
  cfg.smagorinsky = smagorinsky;
}

}  // namespace ship_lrm::tools
