#include "dem/glyph_tensors.hpp"

namespace partimix::dem {

Mat3 shape_tensor(const Quaternion& orientation, const Vec3& half_axes) {
  const Mat3 rotation = orientation.toRotationMatrix();
  return rotation * half_axes.asDiagonal() * rotation.transpose();
}

Mat3 superquadric_glyph_axes(const Quaternion& orientation, const Vec3& half_axes) {
  const Mat3 rotation = orientation.toRotationMatrix();
  Mat3 axes;
  axes.col(0) = half_axes.x() * rotation.col(0);
  axes.col(1) = half_axes.z() * rotation.col(2);
  axes.col(2) = -half_axes.y() * rotation.col(1);
  return axes;
}

}  // namespace partimix::dem
