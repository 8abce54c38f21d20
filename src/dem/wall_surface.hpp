#pragma once
// The surface of a DEM wall (docs/dem.md, "Walls"), in the wall's own frame (where it is at
// t = 0; the solver moves sphere centres into that frame with the wall's motion). A sphere
// touches a surface at the surface point nearest its centre: one contact per wall and sphere.
#include "core/vec.hpp"

namespace partimix::dem {

struct SurfacePoint {
  Vec3 point = Vec3::Zero();    // the nearest point of the surface
  Vec3 normal = Vec3::UnitZ();  // unit, from the surface towards the sphere's side
  double gap = 0.0;             // (centre - point) . normal: overlap = R - gap
};

class WallSurface {
 public:
  virtual ~WallSurface() = default;
  // The nearest point to `centre`; false when the centre lies farther than `reach` from the
  // surface on its side (no contact possible).
  virtual bool nearest(const Vec3& centre, double reach, SurfacePoint& out) const = 0;
};

}  // namespace partimix::dem
