#pragma once
// Expectations on a contact surface's answer (geometry/surface.hpp), to 1e-12: the nearest
// point, the unit normal towards the material side and the gap, and that they agree with each
// other (centre = point + gap normal).
#include <gtest/gtest.h>

#include "geometry/surface.hpp"

namespace partimix::geometry::testing {

constexpr double kSurfaceTolerance = 1e-12;

inline void expect_contact(const Surface& surface, const Vec3& centre, double reach,
                           const Vec3& point, const Vec3& normal, double gap) {
  SurfacePoint s;
  ASSERT_TRUE(surface.nearest(centre, reach, s)) << "centre " << centre.transpose();
  EXPECT_LT((s.point - point).norm(), kSurfaceTolerance)
      << "point " << s.point.transpose() << ", expected " << point.transpose();
  EXPECT_LT((s.normal - normal).norm(), kSurfaceTolerance)
      << "normal " << s.normal.transpose() << ", expected " << normal.transpose();
  EXPECT_NEAR(s.gap, gap, kSurfaceTolerance);
  EXPECT_LT((s.point + s.gap * s.normal - centre).norm(), kSurfaceTolerance);
}

inline void expect_no_contact(const Surface& surface, const Vec3& centre, double reach) {
  SurfacePoint s;
  EXPECT_FALSE(surface.nearest(centre, reach, s)) << "centre " << centre.transpose();
}

}  // namespace partimix::geometry::testing
