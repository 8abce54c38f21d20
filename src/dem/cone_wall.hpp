#pragma once
// The inside of a cone frustum (a hopper): axis through `axis_point` along `axis`; radius r0 at
// the axial coordinate z0 = 0 and r1 at z1 > 0 (z = (x - axis_point) . axis); the spheres stay
// inside. Its two circular rims are open; a sphere near a rim touches the rim's nearest point.
#include "dem/wall_surface.hpp"

namespace partimix::dem {

class ConeWall final : public WallSurface {
 public:
  ConeWall(const Vec3& axis_point, const Vec3& axis, double radius_0, double radius_1,
           double height);
  bool nearest(const Vec3& centre, double reach, SurfacePoint& out) const override;

 private:
  Vec3 axis_point_;
  Vec3 axis_;
  double radius_0_;
  double height_;
  double slope_dz_;  // the unit generator (dz, dr) in the meridian plane
  double slope_dr_;
  double length_;  // of the generator
};

}  // namespace partimix::dem
