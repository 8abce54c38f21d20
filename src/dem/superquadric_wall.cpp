#include "dem/superquadric_wall.hpp"

#include <array>
#include <cmath>
#include <limits>

#include "dem/superquadric_edge_contact.hpp"
#include "geometry/contact_selection.hpp"

namespace partimix::dem {
namespace {

constexpr int kIterations = 20;
constexpr double kNormalTolerance = 1e-20;  // |n_{k+1} - n_k|^2: 1e-10 rad
constexpr int kFewFaces = 4;
constexpr int kRidgesNear = 32;
constexpr double kOnSegment = 1e-9;  // of the segment's length

// The grain against face `face` alone by the support-point iteration ("Walls and
// superquadrics"); `on_ridge` when it reaches a convex edge or corner, whose contact is then
// found by superquadric_face_contact.
WallContact face_iteration(const Superquadric& shape, const Vec3& centre, const Mat3& rotation,
                           const geometry::Surface& surface, int face, bool& on_ridge) {
  const double reach = shape.bounding_radius();
  geometry::SurfacePoint at;
  WallContact contact{false,        true, Vec3::UnitZ(), -std::numeric_limits<double>::infinity(),
                      Vec3::Zero(), {}};
  // The start: the face's normal at its point nearest the centre, whatever the gap there (the
  // face lies within reach: faces_near).
  if (!surface.nearest_on_face(face, centre, std::numeric_limits<double>::infinity(), at) ||
      !std::isfinite(at.gap))
    return contact;  // out of sight (MeshShellSurface::nearest_on_face)
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
    if (geometry::Ridge ridge; surface.ridge(at, ridge)) {
      on_ridge = true;
      return contact;
    }
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

// Whether an edge's contact belongs to its segment: the foot of the wall point on the edge's line
// lies on the segment (a corner's always does).
bool on_segment(const WallContact& contact, const geometry::Ridge& ridge) {
  const Vec3 along = ridge.end - ridge.start;
  if (ridge.count > 2 || along.squaredNorm() == 0.0)
    return true;
  const double s = (contact.wall.point - ridge.start).dot(along) / along.squaredNorm();
  return s >= -kOnSegment && s <= 1.0 + kOnSegment;
}

}  // namespace

// Near the convex edges and corners of the face the wall is the solid behind several faces. The
// face's plane, an edge's wedge and a corner's cone each hold that solid, so each gives an upper
// bound on the grain's overlap with it, and the least of them is the overlap (docs/dem.md,
// "Walls and superquadrics", Convex edges and corners): the iteration's contact when it stays
// on the face, and each edge whose contact lies on its segment and each corner within reach.
WallContact superquadric_face_contact(const Superquadric& shape, const Vec3& centre,
                                      const Mat3& rotation, const geometry::Surface& surface,
                                      int face) {
  bool on_ridge = false;
  WallContact least = face_iteration(shape, centre, rotation, surface, face, on_ridge);
  std::array<geometry::Ridge, kRidgesNear> ridges;
  const int count = surface.ridges_near(face, centre, 2.0 * shape.bounding_radius(), ridges);
  if (on_ridge)
    least.overlap = std::numeric_limits<double>::infinity();
  bool converged = least.converged;
  for (int k = 0; k < count; ++k) {
    const WallContact edge = edge_contact(shape, centre, rotation, ridges[k]);
    converged = converged && edge.converged;
    if (on_segment(edge, ridges[k]) && edge.overlap < least.overlap)
      least = edge;
  }
  if (least.overlap == std::numeric_limits<double>::infinity())
    least.overlap = -least.overlap;
  least.touching = least.overlap > 0.0;
  least.converged = converged;
  return least;
}

namespace {

// Drops from `found` each contact whose face meets the face of a contact with less overlap at a
// convex edge (Surface::convex_neighbours): near it the wall is one convex solid, which a convex
// grain meets once, and each face's contact is an upper bound on the overlap with it. Returns
// the number kept, first in `found`.
int drop_convex_alternatives(const geometry::Surface& surface, std::span<WallContact> found) {
  std::array<bool, kFaceCandidates> dropped{};
  for (std::size_t k = 0; k < found.size(); ++k) {
    for (std::size_t j = 0; j < found.size() && !dropped[k]; ++j) {
      const bool less =
          found[j].overlap < found[k].overlap || (found[j].overlap == found[k].overlap && j < k);
      dropped[k] =
          j != k && less && surface.convex_neighbours(found[j].wall.face, found[k].wall.face);
    }
  }
  std::size_t kept = 0;
  for (std::size_t k = 0; k < found.size(); ++k) {
    if (!dropped[k])
      found[kept++] = found[k];
  }
  return static_cast<int>(kept);
}

// The touching contacts of the faces in `faces`, gathered in `found` (at least as long):
// alternatives across convex edges dropped (touching or not: a face apart can show that its
// convex neighbour's contact is not one), then those not touching, then shadowed ones.
int touching_face_contacts(const Superquadric& shape, const Vec3& centre, const Mat3& rotation,
                           const geometry::Surface& surface, std::span<const int> faces,
                           std::span<WallContact> found, std::span<WallContact> out,
                           int& failures) {
  int measured = 0;
  for (const int face : faces) {
    const WallContact contact = superquadric_face_contact(shape, centre, rotation, surface, face);
    failures += contact.converged ? 0 : 1;
    if (std::isfinite(contact.overlap))
      found[measured++] = contact;
  }
  const int kept = drop_convex_alternatives(surface, found.first(measured));
  int touching = 0;
  for (int k = 0; k < kept; ++k) {
    if (found[k].touching)
      found[touching++] = found[k];
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
