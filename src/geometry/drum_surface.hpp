#pragma once
// The inside of an infinite circular cylinder (a drum shell) as a contact surface: axis through
// `axis_point` along `axis` (normalised here), radius R_d; the material side is the inside. Its
// ends are other walls or periodic boundaries.
//
// Returns, for a centre at distance r from the axis: point = the foot on the shell along the
// centre's radial line, normal = towards the axis, gap = R_d - r (negative outside the shell);
// false when gap > reach, and on the axis itself (r = 0, where no nearest point is preferred).
#include "geometry/surface.hpp"

namespace partimix::geometry {

class DrumSurface final : public Surface {
 public:
  DrumSurface(const Vec3& axis_point, const Vec3& axis, double radius)
      : axis_point_(axis_point), axis_(axis.normalized()), radius_(radius) {}
  bool nearest(const Vec3& centre, double reach, SurfacePoint& out) const override;

 private:
  Vec3 axis_point_;
  Vec3 axis_;
  double radius_;
};

}  // namespace partimix::geometry
