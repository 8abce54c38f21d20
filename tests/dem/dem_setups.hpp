#pragma once
// Set-ups shared by the DEM solver tests: a plane wall of steel and a cubic box domain.
#include <memory>

#include "dem/config.hpp"
#include "geometry/plane_surface.hpp"
#include "particles/domain.hpp"

namespace partimix::dem::test {

inline void add_plane(Config& config, const Vec3& point, const Vec3& normal) {
  config.walls.push_back(
      {std::make_shared<geometry::PlaneSurface>(point, normal), {}, {2.0e11, 0.3}, {}});
}

inline Domain box(double half) {
  Domain domain;
  domain.lo = Vec3::Constant(-half);
  domain.hi = Vec3::Constant(half);
  return domain;
}

}  // namespace partimix::dem::test
