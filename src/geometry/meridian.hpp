#pragma once
// Cylindrical coordinates about an axis, for the shapes and surfaces of revolution (drum, cone,
// cylinder): x = axis_point + z axis + r e_r, with r >= 0 the distance from the axis. Their
// nearest-point and distance problems reduce to two dimensions in the meridian half-plane
// (z, r) through x, and the answer is mapped back to 3D with e_r.
#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>  // unitOrthogonal

#include "core/vec.hpp"

namespace partimix::geometry {

struct Meridian {
  double z = 0.0;            // axial coordinate
  double r = 0.0;            // distance from the axis
  Vec3 e_r = Vec3::UnitX();  // unit, from the axis towards x; any normal to the axis when r = 0
};

// `unit_axis` must have unit length.
inline Meridian meridian(const Vec3& x, const Vec3& axis_point, const Vec3& unit_axis) {
  const Vec3 offset = x - axis_point;
  Meridian m;
  m.z = offset.dot(unit_axis);
  const Vec3 radial = offset - m.z * unit_axis;
  m.r = radial.norm();
  m.e_r = m.r > 0.0 ? Vec3(radial / m.r) : unit_axis.unitOrthogonal();
  return m;
}

// The distance from (z, r) to the segment from (z_a, r_a) to (z_b, r_b) in the meridian plane.
inline double meridian_segment_distance(double z, double r, double z_a, double r_a, double z_b,
                                        double r_b) {
  const double dz = z_b - z_a;
  const double dr = r_b - r_a;
  const double length_squared = dz * dz + dr * dr;
  double t = 0.0;
  if (length_squared > 0.0)
    t = std::clamp(((z - z_a) * dz + (r - r_a) * dr) / length_squared, 0.0, 1.0);
  return std::hypot(z - (z_a + t * dz), r - (r_a + t * dr));
}

}  // namespace partimix::geometry
