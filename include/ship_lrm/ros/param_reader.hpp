// Reading ROS parameters with their types checked. ros::NodeHandle::param falls back to its default
// silently when a parameter has another type: `roslaunch ... lrm_timeout:=inf` gives the string
// "inf" (roslaunch makes a number only of what int() or, with a dot, float() reads), and the flight
// model then ran with its 30 s. Here a parameter that is present must have the type asked for.
#pragma once
#include <ros/node_handle.h>

#include <stdexcept>
#include <string>

namespace ship_lrm::ros_layer {

// A parameter that cannot be used; what() names it and says why.
class ParamError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A parameter of type T (bool, int, std::string, std::vector<std::string>, ...): absent keeps
// `value`; present with another type is a ParamError naming it.
template <typename T>
void read_param(const ros::NodeHandle& nh, const std::string& name, T& value) {
  if (!nh.hasParam(name)) return;
  T v{};
  if (!nh.getParam(name, v)) throw ParamError("parameter " + nh.resolveName(name) + " has the wrong type");
  value = v;
}

// A number (a double, an int as roslaunch makes of "30", or text that is wholly a number as it makes
// of "1e3"): absent keeps `value`; present and not a finite number is a ParamError naming it.
void read_number_param(const ros::NodeHandle& nh, const std::string& name, double& value);

// The same, returning the parameter or `fallback` when it is absent: a number (read_number_param)
// for a double fallback, else exactly the fallback's type.
inline double param_or(const ros::NodeHandle& nh, const std::string& name, double fallback) {
  read_number_param(nh, name, fallback);
  return fallback;
}
template <typename T>
T param_or(const ros::NodeHandle& nh, const std::string& name, T fallback) {
  read_param(nh, name, fallback);
  return fallback;
}

}  // namespace ship_lrm::ros_layer
