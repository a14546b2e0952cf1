// The ship and the sea in the LRM domain (see ship_walls.hpp).
#include "ship_lrm/lrm/ship_walls.hpp"

#include <cmath>
#include <limits>

namespace ship_lrm::lrm {

ShipWall::ShipWall(std::shared_ptr<const wake::ShipGeometry> ship, std::shared_ptr<const wake::ShipMotion> motion)
    : ship_(std::move(ship)), motion_(std::move(motion)) {
  if (!ship_ || !motion_) throw ConfigError("ShipWall: no ship geometry or motion");
}

void ShipWall::place(double t, const DomainPose& pose) {
  const wake::ShipPlacement s = motion_->placement(t);
  // p (domain) -> x = hub + R p (mean) -> body = c + Rs^T (x + heave e_z - c)
  to_body_ = s.rotation.transpose() * pose.rotation;
  body_offset_ = s.to_body(pose.hub);
  // The ship's velocity field in the mean frame, v(x) = v_c + Omega x (x - c_mean), seen from the domain
  // (translating with the hub, turning at pose.omega): R^T (v(hub + R r) - v_hub) - omega x r.
  const Vec3 omega = motion_->omega(t);
  const Vec3 c_mean = s.to_mean(s.centre);
  relative_.velocity = pose.rotation.transpose() * (motion_->centre_velocity(t) + omega.cross(pose.hub - c_mean) - pose.hub_velocity);
  relative_.omega = pose.rotation.transpose() * omega - pose.omega;
}

ShipInDomain::ShipInDomain(std::shared_ptr<const wake::ShipGeometry> ship, std::shared_ptr<const wake::ShipMotion> motion, bool sea)
    : ship_(std::make_shared<ShipWall>(ship, motion)), waterline_(ship ? ship->datum().waterline : 0.0) {
  if (sea) {
    sea_ = std::make_shared<GroundPlane>(1.0);
    sea_->set_clear_of_faces(true);
  }
}

bool ShipInDomain::apply(LrmDomain& domain, double t, const DomainPose& pose) {
  ship_->place(t, pose);
  if (sea_) {
    // solid where the mean-frame z exceeds the waterline: p . (R^T e_z) > waterline - hub_z
    sea_->set_pose(waterline_ - pose.hub.z(), pose.rotation.transpose() * Vec3::UnitZ());
    sea_->set_motion({-(pose.rotation.transpose() * pose.hub_velocity), -pose.omega});
  }
  const double half = 0.5 * domain.cells_per_edge() * domain.units().dx();
  std::array<Vec3, 8> body, mean;
  for (int c = 0; c < 8; ++c) {
    const Vec3 p(c & 1 ? half : -half, c & 2 ? half : -half, c & 4 ? half : -half);
    body[c] = ship_->body_point(p);
    mean[c] = pose.to_mean(p);
  }
  bool due = &domain != domain_;
  const double limit = 0.25 * domain.units().dx();
  for (int c = 0; c < 8 && !due; ++c)
    due = (body[c] - corners_body_[c]).norm() > limit || (sea_ && std::abs(mean[c].z() - corners_mean_[c].z()) > limit);
  if (!due) {
    domain.update_wall_motions();
    if (domain.config().rotor_far_field) place_far_field_ground(domain);
    return false;
  }
  if (&domain != domain_) {
    domain.add_wall(ship_);
    if (sea_) domain.add_wall(sea_);
    domain_ = &domain;
  } else {
    domain.update_walls();
  }
  corners_body_ = body;
  corners_mean_ = mean;
  ++voxelisations_;
  if (domain.config().rotor_far_field) place_far_field_ground(domain);  // after the walls: a ship over the disk is refused there
  return true;
}

void ShipInDomain::place_far_field_ground(LrmDomain& domain) {
  // The first surface straight below the hub (the mr frame's +z), ship or sea, by sphere tracing the
  // two signed distances (each at most the true distance to its surface, so no step passes through
  // one). Not found within 20 R: no ground.
  const double radius = domain.config().radius, step_min = 0.01 * domain.units().dx();
  double z = 0, height = std::numeric_limits<double>::infinity();
  while (z < 20.0 * radius) {
    const Vec3 p(0, 0, z);
    double d = ship_->signed_distance(p);
    if (sea_) d = std::min(d, sea_->signed_distance(p));
    if (d < step_min) {
      height = z;
      break;
    }
    z += d;
  }
  // a new image costs a new far field: only when the surface moved by half a cell (0.3 m at N = 32,
  // against heights of 5 - 15 m above deck or sea)
  const bool both_none = std::isinf(height) && std::isinf(far_field_ground_);
  if (both_none ||
      (!std::isinf(height) && !std::isinf(far_field_ground_) && std::abs(height - far_field_ground_) <= 0.5 * domain.units().dx()))
    return;
  domain.set_far_field_ground(height);
  far_field_ground_ = height;
}

}  // namespace ship_lrm::lrm
