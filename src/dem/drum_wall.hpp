#pragma once
// The inside of an infinite circular cylinder (a drum shell): axis through `axis_point` along
// `axis`, radius R_d; the spheres stay inside. Its ends are planes or periodic boundaries.
#include "dem/wall_surface.hpp"

namespace partimix::dem {

class DrumWall final : public WallSurface {
 public:
  DrumWall(const Vec3& axis_point, const Vec3& axis, double radius)
      : axis_point_(axis_point), axis_(axis.normalized()), radius_(radius) {}
  bool nearest(const Vec3& centre, double reach, SurfacePoint& out) const override;

 private:
  Vec3 axis_point_;
  Vec3 axis_;
  double radius_;
};

}  // namespace partimix::dem
