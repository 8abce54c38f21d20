#include "dem/superquadric_wall.hpp"

namespace partimix::dem {
namespace {

constexpr int kIterations = 20;
constexpr double kNormalTolerance = 1e-20;  // |n_{k+1} - n_k|^2: 1e-10 rad

}  // namespace

WallContact superquadric_wall_contact(const Superquadric& shape, const Vec3& centre,
                                      const Mat3& rotation, const geometry::Surface& surface) {
  const double reach = shape.bounding_radius();
  geometry::SurfacePoint at;
  WallContact contact;
  if (!surface.nearest(centre, reach, at) || at.gap >= reach)
    return contact;
  Vec3 normal = at.normal;
  for (int k = 0;; ++k) {
    const Vec3 deepest = centre + rotation * shape.support(rotation.transpose() * (-normal));
    if (!surface.nearest(deepest, 2.0 * reach, at))
      return contact;
    const bool settled = (at.normal - normal).squaredNorm() < kNormalTolerance;
    normal = at.normal;
    if (settled || k + 1 == kIterations) {
      contact.converged = settled;
      contact.touching = at.gap < 0.0;
      contact.normal = normal;
      contact.overlap = -at.gap;
      contact.point = deepest + 0.5 * contact.overlap * normal;
      return contact;
    }
  }
}

}  // namespace partimix::dem
