#include "geometry/box_container_surface.hpp"

#include <algorithm>
#include <limits>

namespace partimix::geometry {
namespace {

bool is_open(const std::vector<Face>& open_faces, int axis, int side) {
  return std::any_of(open_faces.begin(), open_faces.end(),
                     [&](const Face& f) { return f.axis == axis && (f.side > 0) == (side > 0); });
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

}  // namespace partimix::geometry
