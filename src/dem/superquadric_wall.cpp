#include "dem/superquadric_wall.hpp"

#include <algorithm>
#include <array>
#include <limits>

#include "geometry/contact_selection.hpp"

namespace partimix::dem {
namespace {

constexpr int kIterations = 20;
constexpr double kNormalTolerance = 1e-20;  // |n_{k+1} - n_k|^2: 1e-10 rad
constexpr int kFewFaces = 4;

}  // namespace

WallContact superquadric_face_contact(const Superquadric& shape, const Vec3& centre,
                                      const Mat3& rotation, const geometry::Surface& surface,
                                      int face) {
  const double reach = shape.bounding_radius();
  geometry::SurfacePoint at;
  WallContact contact{false, true, Vec3::UnitZ(), 0.0, Vec3::Zero(), {}};
  // The start: the face's normal at its point nearest the centre, whatever the gap there (the
  // face lies within reach: faces_near).
  surface.nearest_on_face(face, centre, std::numeric_limits<double>::infinity(), at);
  Vec3 normal = at.normal;
  const bool convex = surface.face_is_convex(face);
  const double centre_gap = at.gap;
  for (int k = 0;; ++k) {
    const Vec3 deepest = centre + rotation * shape.support(rotation.transpose() * (-normal));
    // The grain's extent along the normal, -(deepest - centre) . normal, short of the gap: a
    // convex face is apart (Surface::face_is_convex), with no further iteration.
    if (k == 0 && convex && centre_gap + (deepest - centre).dot(normal) > 0.0)
      return contact;
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

namespace {

// The touching contacts of the `count` faces in `faces`, gathered in `found` (at least count
// long), shadowed ones dropped.
int touching_face_contacts(const Superquadric& shape, const Vec3& centre, const Mat3& rotation,
                           const geometry::Surface& surface, std::span<const int> faces,
                           std::span<WallContact> found, std::span<WallContact> out,
                           int& failures) {
  int touching = 0;
  for (const int face : faces) {
    const WallContact contact = superquadric_face_contact(shape, centre, rotation, surface, face);
    failures += contact.converged ? 0 : 1;
    if (contact.touching)
      found[touching++] = contact;
  }
  return geometry::select_contacts(
      surface, found.first(touching), out,
      [](const WallContact& c) -> const geometry::SurfacePoint& { return c.wall; });
}

}  // namespace

int superquadric_wall_contacts(const Superquadric& shape, const Vec3& centre, const Mat3& rotation,
                               const geometry::Surface& surface, std::span<WallContact> out,
                               int& failures) {
  std::array<int, kFaceCandidates> faces;
  const int count = surface.faces_near(centre, shape.bounding_radius(), faces);
  const std::span<const int> near(faces.data(), static_cast<std::size_t>(count));
  // Most grains meet one face of a wall: a short buffer then, which costs less to construct.
  if (count <= kFewFaces) {
    std::array<WallContact, kFewFaces> found;
    return touching_face_contacts(shape, centre, rotation, surface, near, found, out, failures);
  }
  std::array<WallContact, kFaceCandidates> found;
  return touching_face_contacts(shape, centre, rotation, surface, near, found, out, failures);
}

}  // namespace partimix::dem
