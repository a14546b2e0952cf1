// A plane of the LRM domain through the hub, for viewers (the ROS layer's lrm/slice, rviz): every
// cell's centre relative to the hub (m, mr axes), the air velocity relative to the grid (m/s, mr
// axes) and whether it is a wall cell (ship, sea, fuselage); and the largest lattice Mach number of
// the plane. Only the plane's cells are read from the solver (a GPU copies only those).
#pragma once
#include <cstdint>
#include <vector>

#include "ship_lrm/lrm/domain.hpp"

namespace ship_lrm::lrm {

struct DomainSlice {
  std::vector<Vec3> position, velocity;
  std::vector<std::uint8_t> wall;
  double max_mach = 0;  // |u| / c_s in lattice units over the plane's fluid cells
};

// normal: 0 (x: a y-z plane), 1 (y: the x-z plane, the thesis' centre plane), 2 (z: the disk's plane).
DomainSlice domain_slice(LrmDomain& domain, int normal);

}  // namespace ship_lrm::lrm
