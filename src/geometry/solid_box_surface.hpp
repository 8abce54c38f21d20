#pragma once
// The outside of an axis-aligned box [lo, hi] (a plate impeller, a baffle) as a contact surface;
// the material side is the outside, and all six faces are closed.
//
// Returns, for a centre outside the box: point = the centre clamped into the box (on a face, an
// edge or a corner), normal = from the point towards the centre (the face's outward normal on
// a face), gap = the distance. For a centre inside the box or on its surface (a deep overlap):
// the nearest face (the first in the order x-, x+, y-, y+, z-, z+ on a tie), point = the
// centre's foot on it, normal = its outward normal, gap = minus the depth. So the gap equals
// Box::signed_distance (positive outside) everywhere. False when gap > reach.
#include "geometry/surface.hpp"

namespace partimix::geometry {

class SolidBoxSurface final : public Surface {
 public:
  SolidBoxSurface(const Vec3& lo, const Vec3& hi) : lo_(lo), hi_(hi) {}
  bool nearest(const Vec3& centre, double reach, SurfacePoint& out) const override;

 private:
  void nearest_face(const Vec3& centre, SurfacePoint& out) const;

  Vec3 lo_;
  Vec3 hi_;
};

}  // namespace partimix::geometry
