#include "dem/superquadric_wall.hpp"

#include <algorithm>
#include <array>
#include <limits>

#include "geometry/contact_selection.hpp"

namespace partimix::dem {
namespace {

constexpr int kIterations = 20;
constexpr double kNormalTolerance = 1e-20;  // |n_{k+1} - n_k|^2: 1e-10 rad

}  // namespace

WallContact superquadric_face_contact(const Superquadric& shape, const Vec3& centre,
                                      const Mat3& rotation, const geometry::Surface& surface,
                                      int face) {
  const double reach = shape.bounding_radius();
  geometry::SurfacePoint at;
  WallContact contact;
  // The start: the face's normal at its point nearest the centre, whatever the gap there (the
  // face lies within reach: faces_near).
  surface.nearest_on_face(face, centre, std::numeric_limits<double>::infinity(), at);
  Vec3 normal = at.normal;
  for (int k = 0;; ++k) {
    const Vec3 deepest = centre + rotation * shape.support(rotation.transpose() * (-normal));
    if (!surface.nearest_on_face(face, deepest, 2.0 * reach, at))
      return contact;
    const bool settled = (at.normal - normal).squaredNorm() < kNormalTolerance;
    normal = at.normal;
    if (settled || k + 1 == kIterations) {
      contact.converged = settled;
      contact.touching = at.gap < 0.0;
      contact.normal = normal;
      contact.overlap = -at.gap;
      contact.point = deepest + 0.5 * contact.overlap * normal;
      contact.wall = at;
      return contact;
    }
  }
}

int superquadric_wall_contacts(const Superquadric& shape, const Vec3& centre, const Mat3& rotation,
                               const geometry::Surface& surface, std::span<WallContact> out,
                               int& failures) {
  std::array<int, kFaceCandidates> faces;
  const int count = surface.faces_near(centre, shape.bounding_radius(), faces);
  std::array<WallContact, kFaceCandidates> found;
  int touching = 0;
  for (int k = 0; k < count; ++k) {
    const WallContact contact =
        superquadric_face_contact(shape, centre, rotation, surface, faces[k]);
    failures += contact.converged ? 0 : 1;
    if (contact.touching)
      found[touching++] = contact;
  }
  return geometry::select_contacts(
      surface, std::span(found.data(), touching), out,
      [](const WallContact& c) -> const geometry::SurfacePoint& { return c.wall; });
}

}  // namespace partimix::dem
