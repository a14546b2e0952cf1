// A plane of the LRM domain through the hub, for viewers (the ROS layer's lrm/slice, rviz): every
// cell's centre relative to the hub (m, mr axes), the air velocity relative to the grid (m/s, mr
// axes) and whether it is a wall cell (ship, sea, fuselage); and the largest lattice Mach number of
// the plane. Only the plane's cells are read from the solver (a GPU copies only those). Its time
// average (SliceAverage) is what the sweeps' and the approach's plane plots show.
#pragma once
#include <cstdint>
#include <vector>

#include "ship_lrm/lrm/domain.hpp"

namespace ship_lrm::lrm {

struct DomainSlice {
  std::vector<Vec3> position, velocity;
  std::vector<std::uint8_t> wall;
  double max_mach = 0;  // |u| / c_s in lattice units over the plane's fluid cells
  // Only with add_undisturbed_air: the air the faces would impose at each point, relative to the grid
  // (LrmDomain::undisturbed_air: the wake table's, or the uniform stream), m/s, mr axes.
  std::vector<Vec3> undisturbed;
};

// normal: 0 (x: a y-z plane), 1 (y: the x-z plane, the thesis' centre plane), 2 (z: the disk's plane).
DomainSlice domain_slice(LrmDomain& domain, int normal);

// Fills s.undisturbed for the domain's faces as they are now.
void add_undisturbed_air(const LrmDomain& domain, DomainSlice& s);

// The time average of one plane's slices. Walls move through the plane in the approach (the ship
// heaves and pitches), so each point's velocities (and undisturbed air) are averaged over the samples
// in which it was fluid; a point is a wall in the mean where it was one in more than half of them
// (velocity zero where it never was fluid). max_mach is the largest of any sample.
class SliceAverage {
 public:
  // The first slice fixes the plane; std::invalid_argument for a later one with other points.
  void add(const DomainSlice& s);
  long samples() const { return samples_; }
  DomainSlice mean() const;

 private:
  DomainSlice sum_;
  std::vector<long> fluid_, walls_;
  long samples_ = 0;
};

}  // namespace ship_lrm::lrm
