#include "dem/superquadric_wall.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "geometry/contact_selection.hpp"

namespace partimix::dem {
namespace {

constexpr int kIterations = 20;
constexpr double kNormalTolerance = 1e-20;  // |n_{k+1} - n_k|^2: 1e-10 rad
constexpr int kFewFaces = 4;
constexpr int kRidgeSteps = 64;  // bisections of the cone: its angle to 2^-64 of it

// The grain's deepest point against the unit normal m (out of the wall): its support point in
// the direction -m.
Vec3 deepest_against(const Superquadric& shape, const Vec3& centre, const Mat3& rotation,
                     const Vec3& m) {
  return centre + rotation * shape.support(rotation.transpose() * (-m));
}

// The grain against the wedge behind a ridge's two faces (docs/dem.md, "Walls and
// superquadrics", Convex edges): along the unit normal m(theta) = cos theta u + sin theta v of the
// cone from normal_a = u towards normal_b the two overlap by f = m . (p - X(m)), p a point of the
// edge and X(m) the grain's deepest point; the contact is the least f over the cone (the
// separating-axis minimum). X is extremal along m, so m . dX = 0 and f' = m' . (p - X(m)): the
// least f is at an end of the cone where f' does not change sign, else where f' = 0, found by
// bisection on the sign of f' (which, unlike f near its least, is not lost in round-off). The
// wall point X + f m is the foot on the end's plane, or on the edge's line where f' = 0; the
// contact belongs to the face of the nearer end, so that it is the same contact as that face's
// own when its deepest point lies over it.
WallContact ridge_contact(const Superquadric& shape, const Vec3& centre, const Mat3& rotation,
                          const geometry::Ridge& ridge) {
  const Vec3& u = ridge.normal_a;
  const Vec3 v = (ridge.normal_b - ridge.normal_b.dot(u) * u).normalized();
  const double cone = std::atan2(ridge.normal_b.dot(v), ridge.normal_b.dot(u));
  const auto normal_at = [&](double angle) {
    return Vec3(std::cos(angle) * u + std::sin(angle) * v);
  };
  const auto slope_at = [&](double angle) {
    const Vec3 turning = -std::sin(angle) * u + std::cos(angle) * v;
    return turning.dot(ridge.start - deepest_against(shape, centre, rotation, normal_at(angle)));
  };
  double angle = 0.0;
  if (slope_at(0.0) < 0.0) {
    angle = cone;
    if (slope_at(cone) > 0.0) {
      double low = 0.0;
      double high = cone;
      for (int step = 0; step < kRidgeSteps && low < high; ++step) {
        const double middle = 0.5 * (low + high);
        (slope_at(middle) < 0.0 ? low : high) = middle;
      }
      angle = 0.5 * (low + high);
    }
  }
  const Vec3 normal = normal_at(angle);
  const Vec3 deepest = deepest_against(shape, centre, rotation, normal);
  const double overlap = normal.dot(ridge.start - deepest);
  const int face = angle <= 0.5 * cone ? ridge.face_a : ridge.face_b;
  return {overlap > 0.0,
          true,
          normal,
          overlap,
          deepest + 0.5 * overlap * normal,
          geometry::SurfacePoint{deepest + overlap * normal, normal, -overlap, face}};
}

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
    if (geometry::Ridge ridge; surface.ridge(at, ridge))
      return ridge_contact(shape, centre, rotation, ridge);
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
