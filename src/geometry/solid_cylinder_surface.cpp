#include "geometry/solid_cylinder_surface.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/meridian.hpp"

namespace partimix::geometry {
namespace {

// Inside (or on) the cylinder the clamp gives no direction: the part of least depth does, side
// then bottom then top on a tie.
SurfacePoint from_inside(const Meridian& m, const Vec3& base, double radius, double height) {
  const Vec3 e_z = Vec3::UnitZ();
  SurfacePoint out{base + radius * m.e_r + m.z * e_z, m.e_r, -(radius - m.r)};
  if (m.z < -out.gap)
    out = {base + m.r * m.e_r, -e_z, -m.z};
  if (height - m.z < -out.gap)
    out = {base + m.r * m.e_r + height * e_z, e_z, -(height - m.z)};
  return out;
}

}  // namespace

bool SolidCylinderSurface::nearest(const Vec3& centre, double reach, SurfacePoint& out) const {
  const Meridian m = meridian(centre, base_, Vec3::UnitZ());
  const double r = std::min(m.r, radius_);
  const double z = std::clamp(m.z, 0.0, height_);
  const double dr = m.r - r;
  const double dz = m.z - z;
  const double distance = std::hypot(dr, dz);
  if (distance > reach)
    return false;
  if (distance > 0.0) {
    const Vec3 e_z = Vec3::UnitZ();
    out = {base_ + r * m.e_r + z * e_z, (dr * m.e_r + dz * e_z) / distance, distance};
  } else {
    out = from_inside(m, base_, radius_, height_);
  }
  return true;
}

}  // namespace partimix::geometry
