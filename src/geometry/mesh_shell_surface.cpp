#include "geometry/mesh_shell_surface.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <utility>

#include "geometry/contact_selection.hpp"

namespace partimix::geometry {
namespace {

// A point within this fraction of the mesh's size from a triangle lies on it.
constexpr double kOnTriangle = 1e-9;

using Corner = std::array<double, 3>;
using Edge = std::pair<Corner, Corner>;  // the smaller corner first

Corner key_of(const Vec3& x) {
  return {x.x(), x.y(), x.z()};
}

Edge edge_of(const Triangle& triangle, int k) {
  const Corner a = key_of(triangle.corner[k]);
  const Corner b = key_of(triangle.corner[(k + 1) % 3]);
  return a < b ? Edge{a, b} : Edge{b, a};
}

}  // namespace

MeshShellSurface::MeshShellSurface(const TriangleSoup& triangles)
    : bvh_(std::make_shared<const TriangleBvh>(triangles)),
      lower_(Vec3::Constant(std::numeric_limits<double>::infinity())),
      upper_(Vec3::Constant(-std::numeric_limits<double>::infinity())) {
  for (const Triangle& triangle : triangles) {
    for (const Vec3& corner : triangle.corner) {
      lower_ = lower_.cwiseMin(corner);
      upper_ = upper_.cwiseMax(corner);
    }
  }
  on_tolerance_ = kOnTriangle * (upper_ - lower_).norm();
  find_neighbours();
  find_flat_parts();
  find_convex_neighbours();
}

MeshShellSurface::MeshShellSurface(std::shared_ptr<const TriangleBvh> bvh, const Vec3& lower,
                                   const Vec3& upper)
    : bvh_(std::move(bvh)), lower_(lower), upper_(upper) {
  on_tolerance_ = kOnTriangle * (upper_ - lower_).norm();
  find_neighbours();
  find_flat_parts();
  find_convex_neighbours();
}

// The neighbour across each edge: the other triangle with the same two corners (bit for bit),
// when exactly two triangles share them.
void MeshShellSurface::find_neighbours() {
  const auto count = static_cast<std::uint32_t>(bvh_->size());
  std::map<Edge, std::vector<std::int32_t>> owners;
  for (std::uint32_t slot = 0; slot < count; ++slot) {
    for (int k = 0; k < 3; ++k)
      owners[edge_of(bvh_->triangle(slot), k)].push_back(static_cast<std::int32_t>(slot));
  }
  neighbours_.assign(count, {-1, -1, -1});
  for (std::uint32_t slot = 0; slot < count; ++slot) {
    for (int k = 0; k < 3; ++k) {
      const std::vector<std::int32_t>& sharing = owners[edge_of(bvh_->triangle(slot), k)];
      if (sharing.size() == 2)
        neighbours_[slot][k] =
            sharing[0] == static_cast<std::int32_t>(slot) ? sharing[1] : sharing[0];
    }
  }
}

// The flat parts: triangles joined across flat edges (either side), by union-find; each part is
// numbered by its smallest slot.
void MeshShellSurface::find_flat_parts() {
  const auto count = static_cast<std::int32_t>(bvh_->size());
  parts_.resize(static_cast<std::size_t>(count));
  for (std::int32_t slot = 0; slot < count; ++slot)
    parts_[slot] = slot;
  const auto root = [&](std::int32_t slot) {
    while (parts_[slot] != slot)
      slot = parts_[slot] = parts_[parts_[slot]];
    return slot;
  };
  for (std::int32_t slot = 0; slot < count; ++slot) {
    const Vec3& normal = bvh_->unit_normal(static_cast<std::uint32_t>(slot));
    for (int k = 0; k < 3; ++k) {
      if (bend(static_cast<std::uint32_t>(slot), k, normal) != Bend::kFlat)
        continue;
      const std::int32_t a = root(slot);
      const std::int32_t b = root(neighbours_[slot][k]);
      parts_[std::max(a, b)] = std::min(a, b);
    }
  }
  for (std::int32_t slot = 0; slot < count; ++slot)
    parts_[slot] = root(slot);
}

MeshShellSurface::Bend MeshShellSurface::bend(std::uint32_t slot, int k,
                                              const Vec3& side_normal) const {
  const std::int32_t other = neighbours_[slot][k];
  if (other < 0 || side_normal.squaredNorm() == 0.0)
    return Bend::kFree;
  const auto neighbour = static_cast<std::uint32_t>(other);
  if (bvh_->unit_normal(neighbour).squaredNorm() == 0.0)
    return Bend::kFree;
  if (side_normal.cross(bvh_->unit_normal(neighbour)).norm() <= kFlat)
    return Bend::kFlat;
  const Vec3& a = bvh_->triangle(slot).corner[k];
  double rise = 0.0;
  for (const Vec3& corner : bvh_->triangle(neighbour).corner) {
    const double height = (corner - a).dot(side_normal);
    rise = std::abs(height) > std::abs(rise) ? height : rise;
  }
  return rise > 0.0 ? Bend::kConcave : Bend::kConvex;
}

bool MeshShellSurface::near_box(const Vec3& centre, double reach) const {
  return (centre.array() > lower_.array() - reach).all() &&
         (centre.array() < upper_.array() + reach).all();
}

bool MeshShellSurface::nearest(const Vec3& centre, double reach, SurfacePoint& out) const {
  if (!near_box(centre, reach))
    return false;
  const ClosestPoint closest = bvh_->nearest(centre);
  const double gap = std::sqrt(closest.distance_squared);
  if (gap > reach || gap == 0.0)
    return false;
  out = {closest.point, (centre - closest.point) / gap, gap, face_towards(closest.slot, centre)};
  return true;
}

int MeshShellSurface::face_towards(std::uint32_t slot, const Vec3& x) const {
  const double height = (x - bvh_->triangle(slot).corner[0]).dot(bvh_->unit_normal(slot));
  return 2 * static_cast<int>(slot) + (height < 0.0 ? 1 : 0);
}

SurfacePoint MeshShellSurface::on_face(int face, const Vec3& point,
                                       const ClosestPoint& closest) const {
  const auto slot = static_cast<std::uint32_t>(face / 2);
  const Vec3 side_normal = (face % 2 == 0 ? 1.0 : -1.0) * bvh_->unit_normal(slot);
  const Vec3 offset = point - closest.point;
  const double distance = std::sqrt(closest.distance_squared);
  if (closest.feature == TriangleFeature::kFace || distance == 0.0)
    return {closest.point, side_normal, offset.dot(side_normal), face};
  const bool behind = (point - bvh_->triangle(slot).corner[0]).dot(side_normal) < 0.0;
  const double sign = behind ? -1.0 : 1.0;
  return {closest.point, sign * offset / distance, sign * distance, face};
}

int MeshShellSurface::contacts(const Vec3& centre, double reach,
                               std::span<SurfacePoint> out) const {
  if (!near_box(centre, reach))
    return 0;
  std::array<ClosestPoint, kCandidates> found;
  const int count = bvh_->within(centre, reach, found, parts_);
  std::array<SurfacePoint, kCandidates> candidates;
  int kept = 0;
  for (int k = 0; k < count; ++k) {
    if (found[k].distance_squared > 0.0)
      candidates[kept++] = on_face(face_towards(found[k].slot, centre), centre, found[k]);
  }
  return select_contacts(*this, std::span(candidates.data(), kept), out);
}

int MeshShellSurface::faces_near(const Vec3& centre, double reach, std::span<int> out) const {
  if (!near_box(centre, reach))
    return 0;
  std::array<ClosestPoint, kCandidates> found;
  const int count = bvh_->within(centre, reach, found, parts_);
  const int kept = std::min(count, static_cast<int>(out.size()));
  for (int k = 0; k < kept; ++k)
    out[k] = face_towards(found[k].slot, centre);
  return kept;
}

// Over a flat part of the mesh the point walks from triangle to triangle, across the flat edge
// it lies beyond, to the triangle it lies over (at most kWalk triangles; out.face says which).
bool MeshShellSurface::nearest_on_face(int face, const Vec3& point, double reach,
                                       SurfacePoint& out) const {
  int current = face;
  for (int walked = 0; walked < kWalk; ++walked) {
    const auto slot = static_cast<std::uint32_t>(current / 2);
    const ClosestPoint closest = bvh_->closest_on(slot, point);
    if (closest.feature == TriangleFeature::kFace) {
      out = on_face(current, point, closest);
      return out.gap <= reach;
    }
    const int next = flat_neighbour(current, point);
    if (next < 0) {
      out = beyond_triangle(current, point, closest);
      return out.gap <= reach;
    }
    current = next;
  }
  out.gap = std::numeric_limits<double>::infinity();
  return false;
}

// The face across the flat edge that `point` lies farthest beyond (by more than the tolerance of
// "on"), on the same side; -1 when it lies beyond no flat edge. (The farthest, not the first: a
// point beyond a corner would else walk back and forth across its two edges.)
int MeshShellSurface::flat_neighbour(int face, const Vec3& point) const {
  const auto slot = static_cast<std::uint32_t>(face / 2);
  const Vec3 side_normal = (face % 2 == 0 ? 1.0 : -1.0) * bvh_->unit_normal(slot);
  const Triangle& triangle = bvh_->triangle(slot);
  int across = -1;
  double farthest = 0.0;
  for (int k = 0; k < 3; ++k) {
    const Vec3 edge = triangle.corner[(k + 1) % 3] - triangle.corner[k];
    const double outside =
        -edge.cross(point - triangle.corner[k]).dot(bvh_->unit_normal(slot)) / edge.norm();
    if (outside > std::max(farthest, on_tolerance_) && bend(slot, k, side_normal) == Bend::kFlat) {
      farthest = outside;
      across = k;
    }
  }
  if (across < 0)
    return -1;
  const auto neighbour = static_cast<std::uint32_t>(neighbours_[slot][across]);
  const bool behind = bvh_->unit_normal(neighbour).dot(side_normal) < 0.0;
  return 2 * static_cast<int>(neighbour) + (behind ? 1 : 0);
}

// On the edge (within the tolerance of "on") or past concave edges only, the plane goes on, for
// a point in front of those edges' neighbours (behind one, the face is out of sight: the
// neighbour's shell lies between them, as the top of a closed box lies between a grain above it
// and the inside of its sides; the gap is then infinite); past a convex or free edge or corner,
// the normal points from it. At a corner the edges that count are the flat part's own edges
// there (part_corner), not a flat diagonal that the triangle has at it.
SurfacePoint MeshShellSurface::beyond_triangle(int face, const Vec3& point,
                                               const ClosestPoint& closest) const {
  const auto slot = static_cast<std::uint32_t>(face / 2);
  const Vec3 side_normal = (face % 2 == 0 ? 1.0 : -1.0) * bvh_->unit_normal(slot);
  const double height = (point - bvh_->triangle(slot).corner[0]).dot(side_normal);
  const Vec3 foot = point - height * side_normal;
  if ((foot - closest.point).squaredNorm() <= on_tolerance_ * on_tolerance_)
    return {foot, side_normal, height, face};
  PartCorner corner;
  if (closest.feature == TriangleFeature::kCorner) {
    corner = part_corner(slot, closest.index, side_normal, point);
  } else {
    corner.concave = bend(slot, closest.index, side_normal) == Bend::kConcave;
    corner.behind = corner.concave && behind_concave_neighbour(slot, closest.index, point);
  }
  if (!corner.concave)
    return on_face(face, point, closest);
  return {foot, side_normal, corner.behind ? std::numeric_limits<double>::infinity() : height,
          face};
}

// The flat part's edges at corner `corner` of triangle `slot`: walked to across the flat edges
// that meet there, both ways round, up to the first edge that is not flat each way. concave:
// every such edge is concave (none where the part goes all round the corner); behind: `point`
// lies behind the neighbour across one of them.
MeshShellSurface::PartCorner MeshShellSurface::part_corner(std::uint32_t slot, int corner,
                                                           const Vec3& side_normal,
                                                           const Vec3& point) const {
  const Vec3 vertex = bvh_->triangle(slot).corner[corner];
  PartCorner result{true, false};
  for (const int first_edge : {corner, (corner + 2) % 3}) {
    std::uint32_t current = slot;
    int edge = first_edge;
    Vec3 normal = side_normal;
    for (int step = 0; step < kWalk; ++step) {
      const Bend seen = bend(current, edge, normal);
      if (seen != Bend::kFlat) {
        result.concave = result.concave && seen == Bend::kConcave;
        result.behind = result.behind ||
                        (seen == Bend::kConcave && behind_concave_neighbour(current, edge, point));
        break;
      }
      Vec3 next_normal;
      normal_across(current, edge, normal, next_normal);
      const auto next = static_cast<std::uint32_t>(neighbours_[current][edge]);
      if (next == slot)
        break;  // all round: the corner lies inside the part
      const Triangle& triangle = bvh_->triangle(next);
      int at = 0;
      while (at < 3 && triangle.corner[at] != vertex)
        ++at;
      if (at == 3)
        break;
      edge = neighbours_[next][at] == static_cast<std::int32_t>(current) ? (at + 2) % 3 : at;
      current = next;
      normal = next_normal;
    }
  }
  return result;
}

// Whether `point` lies behind the neighbour across concave edge k of triangle `slot`: on the side
// of the neighbour's plane away from the triangle (whose corner off the edge lies in front).
bool MeshShellSurface::behind_concave_neighbour(std::uint32_t slot, int k,
                                                const Vec3& point) const {
  const auto neighbour = static_cast<std::uint32_t>(neighbours_[slot][k]);
  const Triangle& triangle = bvh_->triangle(slot);
  const Vec3& normal = bvh_->unit_normal(neighbour);
  const double off_edge = (triangle.corner[(k + 2) % 3] - triangle.corner[k]).dot(normal);
  const double height = (point - triangle.corner[k]).dot(normal);
  return (off_edge > 0.0 ? height : -height) < -on_tolerance_;
}

// The candidate is a point of the deeper one's flat part when both come from one part, when it
// lies on an edge (or at a corner, either edge) whose neighbour belongs to that part, or when it
// lies on the deeper one's triangle.
bool MeshShellSurface::shadowed(const SurfacePoint& candidate, const SurfacePoint& deeper) const {
  const auto slot = static_cast<std::uint32_t>(candidate.face / 2);
  const auto other = static_cast<std::uint32_t>(deeper.face / 2);
  const std::int32_t part = parts_[other];
  if (parts_[slot] == part)
    return true;
  const ClosestPoint own = bvh_->closest_on(slot, candidate.point);
  if (own.feature != TriangleFeature::kFace) {
    const int first = own.index;
    const int second = own.feature == TriangleFeature::kCorner ? (first + 2) % 3 : first;
    for (const int k : {first, second}) {
      const std::int32_t neighbour = neighbours_[slot][k];
      if (neighbour >= 0 && parts_[neighbour] == part)
        return true;
    }
  }
  return bvh_->closest_on(other, candidate.point).distance_squared <= on_tolerance_ * on_tolerance_;
}

}  // namespace partimix::geometry
