#pragma once
// An infinite plane through `point` with unit `normal`; the spheres stay on the normal's side.
#include "dem/wall_surface.hpp"

namespace partimix::dem {

class PlaneWall final : public WallSurface {
 public:
  PlaneWall(const Vec3& point, const Vec3& normal) : point_(point), normal_(normal.normalized()) {}
  bool nearest(const Vec3& centre, double reach, SurfacePoint& out) const override {
    const double gap = (centre - point_).dot(normal_);
    if (gap > reach)
      return false;
    out = {centre - gap * normal_, normal_, gap};
    return true;
  }

 private:
  Vec3 point_;
  Vec3 normal_;
};

}  // namespace partimix::dem
