// ROS parameters -> lrm::ApproachConfig (see approach_params.hpp).
#include "ship_lrm/ros/approach_params.hpp"

#include <cmath>
#include <cstdlib>
#include <filesystem>

#include "ship_lrm/lbm/solver.hpp"
#include "ship_lrm/lrm/face_setup.hpp"
#include "ship_lrm/wake/wake_precompute.hpp"

namespace ship_lrm::ros_layer {
namespace {

std::string where(const ros::NodeHandle& nh, const std::string& name) { return nh.resolveName(name); }

}  // namespace

void read_number_param(const ros::NodeHandle& nh, const std::string& name, double& value) {
  if (!nh.hasParam(name)) return;
  double d = 0;
  int i = 0;
  std::string text;
  if (nh.getParam(name, d)) {
    value = d;
  } else if (nh.getParam(name, i)) {
    value = i;
  } else if (nh.getParam(name, text)) {
    // roslaunch types an argument as a number only when int() or, with a dot, float() reads it:
    // `speed:=1e3` arrives as the text "1e3"; take it when the whole text is a number
    char* end = nullptr;
    value = std::strtod(text.c_str(), &end);
    if (text.empty() || end != text.c_str() + text.size())
      throw ParamError("parameter " + nh.resolveName(name) + " must be a number, got '" + text + "'");
  } else {
    throw ParamError("parameter " + nh.resolveName(name) + " must be a number");
  }
  if (!std::isfinite(value)) throw ParamError("parameter " + nh.resolveName(name) + " must be finite");
}

lrm::ApproachConfig approach_config(const ros::NodeHandle& nh, bool table_here) {
  lrm::ApproachConfig c;
  read_param(nh, "wake_file", c.table);
  std::string preset;
  c.table = wake::named_table(c.table, preset);
  if (table_here && !std::filesystem::exists(c.table)) throw ParamError(wake::missing_table_message(c.table, preset));
  read_param(nh, "inflow", c.inflow);
  if (c.inflow != "lrm" && c.inflow != "pitt_peters")
    throw ParamError("parameter " + where(nh, "inflow") + " must be lrm or pitt_peters, got '" + c.inflow + "'");
  int nodes = 32;  // as `ship_lrm approach`
  read_param(nh, "N", nodes);
  if (nodes < 16 || nodes > 512) throw ParamError("parameter " + where(nh, "N") + " must lie in [16, 512], got " + std::to_string(nodes));
  c.lrm.nodes = nodes;
  read_number_param(nh, "reach", c.lrm.reach);
  if (!(c.lrm.reach >= 1.0 && c.lrm.reach <= 8.0))
    throw ParamError("parameter " + where(nh, "reach") + " must lie in [1, 8] (domain edge / 4R), got " + std::to_string(c.lrm.reach));
  std::string backend = "auto";
  read_param(nh, "backend", backend);
  try {
    c.lrm.backend = lbm::parse_backend(backend);
  } catch (const std::exception& e) {
    throw ParamError("parameter " + where(nh, "backend") + ": " + e.what());
  }
  // the LRM's faces, as `ship_lrm approach --faces --outlet-sigma --relaxed-faces --rotor-far-field`
  std::string faces = "thesis";
  read_param(nh, "faces", faces);
  double sigma = 0;
  read_number_param(nh, "outlet_sigma", sigma);
  std::vector<std::string> relaxed = {"back", "top", "bottom"};
  read_param(nh, "relaxed_faces", relaxed);
  try {
    lrm::apply_face_setup(faces, c.lrm);
    lrm::relax_faces(relaxed, sigma, c.lrm);
  } catch (const std::exception& e) {
    throw ParamError("parameters " + where(nh, "faces") + ", " + where(nh, "outlet_sigma") + ", " + where(nh, "relaxed_faces") + ": " +
                     e.what());
  }
  read_param(nh, "rotor_far_field", c.lrm.rotor_far_field);
  read_number_param(nh, "duration", c.duration);
  read_number_param(nh, "startup", c.startup);
  read_number_param(nh, "table_offset", c.table_offset);
  read_number_param(nh, "trim_speed", c.trim_speed);
  read_number_param(nh, "lattice_margin", c.lattice_margin);
  read_param(nh, "ship_walls", c.ship_walls);
  read_param(nh, "fuselage", c.fuselage);
  read_param(nh, "wake", c.wake);
  read_param(nh, "free_flight", c.free_flight);
  read_number_param(nh, "path/start_distance", c.path.start_distance);
  read_number_param(nh, "path/height", c.path.height);
  read_number_param(nh, "path/lateral", c.path.lateral);
  read_number_param(nh, "path/speed", c.path.speed);
  read_number_param(nh, "path/decelerate_at", c.path.decelerate_at);
  read_number_param(nh, "path/hover_at", c.path.hover_at);
  try {
    lrm::validate(c);
  } catch (const std::exception& e) {
    throw ParamError(std::string("parameters under ") + nh.getNamespace() + ": " + e.what());
  }
  return c;
}

}  // namespace ship_lrm::ros_layer
