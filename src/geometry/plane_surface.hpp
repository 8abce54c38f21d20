#pragma once
// An infinite plane through `point` with unit `normal` (normalised here) as a contact surface;
// the material side is the normal's side.
//
// Returns, for every centre: point = the centre's foot on the plane, the normal, and
// gap = (centre - point) . normal, negative behind the plane; false when gap > reach.
#include "geometry/surface.hpp"

namespace partimix::geometry {

class PlaneSurface final : public Surface {
 public:
  PlaneSurface(const Vec3& point, const Vec3& normal)
      : point_(point), normal_(normal.normalized()) {}
  bool nearest(const Vec3& centre, double reach, SurfacePoint& out) const override;
  bool face_is_convex(int /*face*/) const override { return true; }

 private:
  Vec3 point_;
  Vec3 normal_;
};

}  // namespace partimix::geometry
