#pragma once
// Small fixed-size vector and tensor types used everywhere (Eigen). 2D runs use the x-y plane
// and keep z = 0, so every field is stored as a 3-vector.
#include <Eigen/Core>

namespace partimix {

using Vec3 = Eigen::Vector3d;
using Vec3f = Eigen::Vector3f;
using Mat3 = Eigen::Matrix3d;

}  // namespace partimix
