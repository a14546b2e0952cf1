// Named set-ups of the LRM domain's six faces (forward-flight inflow target), shared by the command-line
// tools (`sweep`, `trim --inflow lrm`, `approach`, `bench lrm`) and the ROS nodelets' parameters.
#pragma once

#include <string>
#include <vector>

#include "ship_lrm/lrm/domain.hpp"

namespace ship_lrm::lrm {

// thesis, open-sides, open, pressure, ambient, ambient-sides (face_setup.cpp says what each is)
const std::vector<std::string>& face_setup_names();
// The faces in LrmConfig::faces' order: back, front, left, right, top, bottom.
const std::vector<std::string>& face_names();

// Sets cfg.faces and cfg.entraining_pressure_faces to the named set-up; ConfigError naming the
// choices for an unknown name.
void apply_face_setup(const std::string& name, LrmConfig& cfg);
// cfg.outlet_sigma = sigma on the named faces (face_names()); ConfigError for an unknown face or a
// sigma outside [0, 10].
void relax_faces(const std::vector<std::string>& faces, double sigma, LrmConfig& cfg);

}  // namespace ship_lrm::lrm
