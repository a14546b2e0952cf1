// Signed-distance bodies of the LRM domain (see walls.hpp).
#include "ship_lrm/lrm/walls.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ship_lrm::lrm {

GroundPlane::GroundPlane(double height, const Vec3& down) : height_(0), down_(Vec3::UnitZ()) { set_pose(height, down); }

void GroundPlane::set_pose(double height, const Vec3& down) {
  if (!std::isfinite(height) || !down.allFinite() || down.norm() < 1e-9)
    throw std::invalid_argument("ground plane: the height must be finite and the down vector non-zero");
  height_ = height;
  down_ = down.normalized();
}

double Fuselage::signed_distance(const Vec3& p) const {
  // Ellipsoid: the scaled-sphere estimate (exact on the axes, a lower bound in magnitude elsewhere,
  // enough to tell inside from outside, which is all the voxelisation needs).
  const Vec3 q = (p - s_.cabin_centre).cwiseQuotient(s_.cabin_semi_axes);
  const double cabin = (q.norm() - 1.0) * s_.cabin_semi_axes.minCoeff();
  // Capsule around the boom segment.
  const Vec3 ab = s_.boom_end - s_.boom_start;
  const double t = std::clamp((p - s_.boom_start).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  const double boom = (p - (s_.boom_start + t * ab)).norm() - s_.boom_radius;
  return std::min(cabin, boom);
}

}  // namespace ship_lrm::lrm
