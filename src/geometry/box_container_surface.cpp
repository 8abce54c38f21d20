#include "geometry/box_container_surface.hpp"

#include <algorithm>
#include <array>
#include <limits>

#include "geometry/contact_selection.hpp"

namespace partimix::geometry {
namespace {

bool is_open(const std::vector<Face>& open_faces, int axis, int side) {
  return std::any_of(open_faces.begin(), open_faces.end(),
                     [&](const Face& f) { return f.axis == axis && (f.side > 0) == (side > 0); });
}

Face face_of(int id) {
  return Face{id / 2, id % 2 == 0 ? -1 : 1};
}

int id_of(const Face& face) {
  return 2 * face.axis + (face.side > 0 ? 1 : 0);
}

Vec3 inward_normal(const Face& face) {
  return -static_cast<double>(face.side) * Vec3::Unit(face.axis);
}

// Whether the centre lies within the face's rectangle seen along the face's axis.
bool within_face(const Vec3& centre, const Vec3& clamped, int axis) {
  for (int other = 0; other < 3; ++other) {
    if (other != axis && centre[other] != clamped[other])
      return false;
  }
  return true;
}

}  // namespace

BoxContainerSurface::BoxContainerSurface(const Vec3& lo, const Vec3& hi,
                                         const std::vector<Face>& open_faces)
    : lo_(lo), hi_(hi) {
  for (int axis = 0; axis < 3; ++axis) {
    for (const int side : {-1, 1}) {
      const bool closed = !is_open(open_faces, axis, side);
      closed_[axis][side > 0] = closed;
      if (closed)
        closed_faces_.push_back(Face{axis, side});
    }
  }
}

// Outside the box across closed faces only: past no open face.
bool BoxContainerSurface::crossed(const Vec3& centre) const {
  bool outside = false;
  for (int axis = 0; axis < 3; ++axis) {
    const bool below = centre[axis] < lo_[axis];
    const bool above = centre[axis] > hi_[axis];
    if ((below && !closed_[axis][0]) || (above && !closed_[axis][1]))
      return false;
    outside = outside || below || above;
  }
  return outside;
}

bool BoxContainerSurface::nearest(const Vec3& centre, double reach, SurfacePoint& out) const {
  const Vec3 clamped = centre.cwiseMax(lo_).cwiseMin(hi_);
  double best = std::numeric_limits<double>::infinity();
  const Face* face = nullptr;
  Vec3 point = clamped;
  for (const Face& candidate : closed_faces_) {
    Vec3 on_face = clamped;
    on_face[candidate.axis] = candidate.side > 0 ? hi_[candidate.axis] : lo_[candidate.axis];
    const double distance_squared = (centre - on_face).squaredNorm();
    if (distance_squared < best) {
      best = distance_squared;
      face = &candidate;
      point = on_face;
    }
  }
  if (face == nullptr)
    return false;
  const Vec3 inward = -static_cast<double>(face->side) * Vec3::Unit(face->axis);
  const Vec3 offset = centre - point;
  Vec3 normal = inward;
  if (!within_face(centre, clamped, face->axis)) {
    // An edge or corner: the centre is outside the box. On the centre itself (distance 0) the
    // face's normal stands in, with gap 0.
    const double distance = offset.norm();
    if (distance > 0.0)
      normal = (crossed(centre) ? -offset : offset) / distance;
  }
  const double gap = offset.dot(normal);
  if (gap > reach)
    return false;
  out = {point, normal, gap};
  return true;
}

bool BoxContainerSurface::nearest_on_face(int face_id, const Vec3& point, double reach,
                                          SurfacePoint& out) const {
  const Face face = face_of(face_id);
  if (!closed_[face.axis][face.side > 0])
    return false;
  bool rim = false;
  for (int other = 0; other < 3; ++other) {
    rim = rim || (other != face.axis && ((point[other] < lo_[other] && !closed_[other][0]) ||
                                         (point[other] > hi_[other] && !closed_[other][1])));
  }
  const Vec3 inward = inward_normal(face);
  if (!rim) {
    Vec3 foot = point;
    foot[face.axis] = plane(face);
    out = {foot, inward, (point - foot).dot(inward), face_id};
    return out.gap <= reach;
  }
  Vec3 on_rim = point.cwiseMax(lo_).cwiseMin(hi_);
  on_rim[face.axis] = plane(face);
  const Vec3 offset = point - on_rim;
  const double distance = offset.norm();
  out = {on_rim, distance > 0.0 ? Vec3(offset / distance) : inward, distance, face_id};
  return distance <= reach;
}

int BoxContainerSurface::face_points(const Vec3& centre, double reach,
                                     std::span<SurfacePoint, 6> out) const {
  int count = 0;
  for (const Face& face : closed_faces_) {
    if (nearest_on_face(id_of(face), centre, reach, out[count]))
      ++count;
  }
  return count;
}

int BoxContainerSurface::contacts(const Vec3& centre, double reach,
                                  std::span<SurfacePoint> out) const {
  std::array<SurfacePoint, 6> candidates;
  const int count = face_points(centre, reach, candidates);
  return select_contacts(*this, std::span(candidates.data(), count), out);
}

int BoxContainerSurface::faces_near(const Vec3& centre, double reach, std::span<int> out) const {
  std::array<SurfacePoint, 6> candidates;
  const int count = face_points(centre, reach, candidates);
  sort_deepest_first(std::span(candidates.data(), count));
  const int kept = std::min(count, static_cast<int>(out.size()));
  for (int k = 0; k < kept; ++k)
    out[k] = candidates[k].face;
  return kept;
}

// A rim point (its normal is not its face's) on the plane of a deeper closed face lies on that
// face's rim too.
bool BoxContainerSurface::shadowed(const SurfacePoint& candidate,
                                   const SurfacePoint& deeper) const {
  const Face face = face_of(candidate.face);
  const Face other = face_of(deeper.face);
  const bool rim = candidate.normal != inward_normal(face);
  return rim && other.axis != face.axis && candidate.point[other.axis] == plane(other);
}

}  // namespace partimix::geometry
