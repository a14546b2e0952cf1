// ROS parameters -> the approach's core configuration (lrm::ApproachConfig), read the same way by
// every nodelet that needs it (FlightModel and LrmSolver must agree, or the loads would differ from
// the batch tool's). The parameters live in one namespace (launch: `approach/`, from
// config/approach.yaml and the launch arguments); names follow `ship_lrm approach`'s options.
#pragma once
#include <ros/node_handle.h>

#include <string>

#include "ship_lrm/lrm/approach_config.hpp"
#include "ship_lrm/ros/param_reader.hpp"

namespace ship_lrm::ros_layer {

// Reads and checks (ParamError naming the parameter): wake_file (a table file; empty or default: the
// default preset's table, realistic: the realistic preset's, wake::named_table; it must exist here
// unless table_here is false: a solver fed by the wake server), inflow, N, reach, backend, duration,
// startup, table_offset, trim_speed, lattice_margin, ship_walls, fuselage, wake, free_flight,
// path/{start_distance, height, lateral, speed, decelerate_at, hover_at}.
lrm::ApproachConfig approach_config(const ros::NodeHandle& nh, bool table_here = true);

}  // namespace ship_lrm::ros_layer
