// The vector and matrix types every module above the LBM core shares: 3-vectors and 3x3 matrices of
// doubles (Eigen). The LBM core itself does without them (it builds without Eigen on a GPU machine).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace ship_lrm {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

}  // namespace ship_lrm
