// The ship and the sea in the LRM domain (the ship walls through a signed-distance provider,
// from the same geometry and motion as the wake table; thesis 6.4, fig. 9.3). The LRM grid is
// fixed to the rotorcraft (domain.hpp), so the ship moves through it: its cells are no-slip walls that
// move with the ship's rigid motion relative to the grid (moving-wall bounce-back), re-voxelised when
// the ship has moved by a quarter cell anywhere in the domain, with the refill of domain.hpp for the
// cells it leaves.
#pragma once
#include <limits>
#include <memory>

#include "ship_lrm/common/vec.hpp"
#include "ship_lrm/lrm/domain.hpp"
#include "ship_lrm/lrm/walls.hpp"
#include "ship_lrm/wake/ship_geometry.hpp"
#include "ship_lrm/wake/ship_motion.hpp"

namespace ship_lrm::lrm {

// Where the LRM domain is in the ship's mean frame (the wake table's frame, ship_motion.hpp) at one
// instant.
struct DomainPose {
  Vec3 hub = Vec3::Zero();           // m, mean frame
  Mat3 rotation = Mat3::Identity();  // mr axes -> mean frame
  Vec3 hub_velocity = Vec3::Zero();  // m/s, mean frame
  Vec3 omega = Vec3::Zero();         // angular velocity of the domain, mr axes, rad/s
  Vec3 to_mean(const Vec3& r) const { return hub + rotation * r; }
};

// The ship's hull as a wall of the LRM domain. place() puts it where it is at ship time t (the wake
// table's time axis) seen from a domain at `pose`.
class ShipWall final : public WallSurface {
 public:
  ShipWall(std::shared_ptr<const wake::ShipGeometry> ship, std::shared_ptr<const wake::ShipMotion> motion);
  std::string name() const override { return "ship"; }
  double signed_distance(const Vec3& p) const override { return ship_->signed_distance(body_point(p)); }
  RigidMotion motion() const override { return relative_; }
  bool clear_of_faces() const override { return true; }  // thesis 6.4 (walls.hpp)
  void place(double t, const DomainPose& pose);
  // The ship-frame point at domain position p (m, mr axes from the hub).
  Vec3 body_point(const Vec3& p) const { return to_body_ * p + body_offset_; }

 private:
  std::shared_ptr<const wake::ShipGeometry> ship_;
  std::shared_ptr<const wake::ShipMotion> motion_;
  Mat3 to_body_ = Mat3::Identity();  // domain position -> ship frame: to_body_ p + body_offset_
  Vec3 body_offset_ = Vec3::Zero();
  RigidMotion relative_;
};

// The ship and the sea surface (flat, at the mean waterline, at rest in the mean frame like the wake
// table's sea) in one LRM domain.
class ShipInDomain {
 public:
  ShipInDomain(std::shared_ptr<const wake::ShipGeometry> ship, std::shared_ptr<const wake::ShipMotion> motion, bool sea = true);
  // Places ship and sea for ship time t and the domain's pose. Re-voxelises the domain (adding the walls
  // at the first call) when the ship or the sea has moved relative to the grid by a quarter cell at
  // any corner of the domain since the last voxelisation; otherwise only their velocities change.
  // Returns whether it re-voxelised. Throws ConfigError when the ship covers a rotor-disk cell.
  bool apply(LrmDomain& domain, double t, const DomainPose& pose);
  std::size_t voxelisations() const { return voxelisations_; }
  // With LrmConfig::rotor_far_field: the height below the hub of the surface (deck or sea) that the far
  // field's wake is mirrored in (LrmDomain::set_far_field_ground), updated by apply(); infinity: none.
  double far_field_ground() const { return far_field_ground_; }

 private:
  void place_far_field_ground(LrmDomain& domain);
  double far_field_ground_ = std::numeric_limits<double>::infinity();
  std::shared_ptr<ShipWall> ship_;
  std::shared_ptr<GroundPlane> sea_;
  double waterline_;
  const LrmDomain* domain_ = nullptr;
  std::size_t voxelisations_ = 0;
  std::array<Vec3, 8> corners_body_;  // the domain's corners in the ship frame at the last voxelisation
  std::array<Vec3, 8> corners_mean_;  // and in the mean frame (the sea)
};

}  // namespace ship_lrm::lrm
