#pragma once
// The outside of a closed circular cylinder along z (a shaft, a hub; the parameters of
// geometry::Cylinder: base centre, radius R, height H) as a contact surface: side and both end
// discs, the material side outside.
//
// Works in the meridian plane through the centre, (r, z) with r the distance from the axis and
// z the height above the base. For a centre outside the cylinder: point = (min(r, R),
// clamp(z, 0, H)) mapped back to 3D (on the side, on a disc or on a rim circle), normal = from
// the point towards the centre (the outward normal on the side or a disc), gap = the distance.
// For a centre inside or on the surface (a deep overlap): the nearest of side, bottom and top
// (in that order on a tie), point = the centre's foot on it, normal = its outward normal, gap =
// minus the depth (on the axis the side's foot lies in any radial direction). So the gap equals
// Cylinder::signed_distance (positive outside) everywhere. False when gap > reach.
#include "geometry/surface.hpp"

namespace partimix::geometry {

class SolidCylinderSurface final : public Surface {
 public:
  SolidCylinderSurface(const Vec3& base_centre, double radius, double height)
      : base_(base_centre), radius_(radius), height_(height) {}
  bool nearest(const Vec3& centre, double reach, SurfacePoint& out) const override;

 private:
  Vec3 base_;
  double radius_;
  double height_;
};

}  // namespace partimix::geometry
