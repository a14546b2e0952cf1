// A wake table whose windows come from the WakeServer nodelet (service wake/window) instead of a file
// here: for an LRM solver on a machine without the table (LrmSolver wake_source:=server). The values
// are the file's own (float32 over the wire), so the solver computes what it would with the file.
#pragma once
#include <ros/node_handle.h>

#include <memory>

#include "ship_lrm/WakeInfo.h"
#include "ship_lrm/wake/wake_table.hpp"

namespace ship_lrm::ros_layer {

// The table announced on wake/info, its windows read through the service `service` (resolved in nh).
// wake::TableError when the announcement is not a usable table; a window that cannot be had (the
// server gone, a refused box) makes the table's reads fail with the server's reason.
std::shared_ptr<wake::WakeTable> served_wake_table(const ship_lrm::WakeInfo& info, const ros::NodeHandle& nh,
                                                   const std::string& service = "wake/window");

}  // namespace ship_lrm::ros_layer
