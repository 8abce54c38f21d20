#pragma once
// The inside of a cone frustum (a hopper) as a contact surface: axis through `axis_point` along
// `axis` (normalised here); radius r0 at the axial coordinate z = 0 and r1 at z = height > 0
// (z = (x - axis_point) . axis). The material side is the inside; the two circular rims are
// open (no end discs).
//
// Returns, in the meridian plane through the centre (z, r): the nearest point of the generator
// segment from (0, r0) to (height, r1), mapped back to 3D.
// - Inside the segment: normal = the generator's inward normal, gap = the signed distance to
//   the cone's lateral surface (positive inside, negative for a centre that crossed it).
// - At a rim (the nearest point is an end of the segment): normal = from the rim towards the
//   centre, gap = the distance, always >= 0 (a rim is touched from either side).
// False when gap > reach, and on the axis (r = 0).
#include "geometry/surface.hpp"

namespace partimix::geometry {

class ConeSurface final : public Surface {
 public:
  ConeSurface(const Vec3& axis_point, const Vec3& axis, double radius_0, double radius_1,
              double height);
  bool nearest(const Vec3& centre, double reach, SurfacePoint& out) const override;

 private:
  Vec3 axis_point_;
  Vec3 axis_;
  double radius_0_;
  double slope_dz_;  // the unit generator (dz, dr) in the meridian plane
  double slope_dr_;
  double length_;  // of the generator
};

}  // namespace partimix::geometry
