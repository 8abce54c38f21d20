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
// Two triangles whose unit normals' cross product is below this are flat across their edge.
constexpr double kFlat = 1e-9;

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
}

MeshShellSurface::MeshShellSurface(std::shared_ptr<const TriangleBvh> bvh, const Vec3& lower,
                                   const Vec3& upper)
    : bvh_(std::move(bvh)), lower_(lower), upper_(upper) {
  on_tolerance_ = kOnTriangle * (upper_ - lower_).norm();
  find_neighbours();
  find_flat_parts();
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

// On the edge (within the tolerance of "on") or past concave edges only, the plane goes on; past
// a convex or free edge or corner, the normal points from it (at corner k the edges k and k + 2
// meet).
SurfacePoint MeshShellSurface::beyond_triangle(int face, const Vec3& point,
                                               const ClosestPoint& closest) const {
  const auto slot = static_cast<std::uint32_t>(face / 2);
  const Vec3 side_normal = (face % 2 == 0 ? 1.0 : -1.0) * bvh_->unit_normal(slot);
  const int first = closest.index;
  const int second = closest.feature == TriangleFeature::kCorner ? (first + 2) % 3 : first;
  const double height = (point - bvh_->triangle(slot).corner[0]).dot(side_normal);
  const Vec3 foot = point - height * side_normal;
  const bool on_edge = (foot - closest.point).squaredNorm() <= on_tolerance_ * on_tolerance_;
  if (on_edge || (bend(slot, first, side_normal) == Bend::kConcave &&
                  bend(slot, second, side_normal) == Bend::kConcave))
    return {foot, side_normal, height, face};
  return on_face(face, point, closest);
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

// The normal of triangle `slot` seen from the grains' side, given the side normal of its
// neighbour across its edge k (`from`): flat, the same way; convex, away from the neighbour's
// corner off that edge; false when the edge is concave (no wedge) or free.
bool MeshShellSurface::normal_across(std::uint32_t from, int k, const Vec3& from_normal,
                                     Vec3& out) const {
  const Bend seen = bend(from, k, from_normal);
  if (seen == Bend::kFree || seen == Bend::kConcave)
    return false;
  const auto slot = static_cast<std::uint32_t>(neighbours_[from][k]);
  const Vec3& normal = bvh_->unit_normal(slot);
  const Triangle& triangle = bvh_->triangle(from);
  const Vec3 off_edge = triangle.corner[(k + 2) % 3] - triangle.corner[k];
  const bool turned =
      seen == Bend::kFlat ? normal.dot(from_normal) < 0.0 : off_edge.dot(normal) > 0.0;
  out = turned ? Vec3(-normal) : normal;
  return true;
}

// A convex edge, or a corner where the triangles around it (walked across the edges that meet
// there) take exactly two normals, as two faces meeting at a straight ridge do. face_b: the
// neighbour across the edge, or at a corner the first triangle met with the other normal; both
// faces hold the ridge's points, so shadowed() keeps a contact on the ridge once.
bool MeshShellSurface::ridge(const SurfacePoint& at, Ridge& out) const {
  const auto slot = static_cast<std::uint32_t>(at.face / 2);
  const Vec3 side_normal = (at.face % 2 == 0 ? 1.0 : -1.0) * bvh_->unit_normal(slot);
  const Triangle& triangle = bvh_->triangle(slot);
  // The edges within the tolerance of "on" of the point: one, an edge; two, their corner.
  std::array<int, 3> on{};
  int count = 0;
  for (int k = 0; k < 3; ++k) {
    const Vec3& a = triangle.corner[k];
    const Vec3 edge = triangle.corner[(k + 1) % 3] - a;
    const double s = std::clamp((at.point - a).dot(edge) / edge.squaredNorm(), 0.0, 1.0);
    if ((at.point - a - s * edge).squaredNorm() <= on_tolerance_ * on_tolerance_)
      on[count++] = k;
  }
  if (count == 0 || count == 3)
    return false;
  if (count == 2) {  // edges k and k + 1 meet at corner k + 1; edges 0 and 2 at corner 0
    const int corner = on[1] == on[0] + 1 ? on[1] : on[0];
    return ridge_at_corner(slot, corner, side_normal, at.face, out);
  }
  const int k = on[0];
  Vec3 other;
  if (bend(slot, k, side_normal) != Bend::kConvex || !normal_across(slot, k, side_normal, other))
    return false;
  const auto neighbour = static_cast<std::uint32_t>(neighbours_[slot][k]);
  const int neighbour_face = 2 * static_cast<int>(neighbour) + seen_side(neighbour, other);
  out = {triangle.corner[k], triangle.corner[(k + 1) % 3], side_normal, other, at.face,
         neighbour_face};
  return true;
}

// Around corner `corner` of triangle `slot`: each step crosses the other edge of the current
// triangle that meets at the corner.
bool MeshShellSurface::ridge_at_corner(std::uint32_t slot, int corner, const Vec3& side_normal,
                                       int face, Ridge& out) const {
  const Vec3 vertex = bvh_->triangle(slot).corner[corner];
  std::uint32_t current = slot;
  Vec3 normal = side_normal;
  int edge = corner;  // edges corner and corner + 2 meet at the corner
  Vec3 other = side_normal;
  int other_face = -1;
  for (int step = 0; step < kWalk; ++step) {
    Vec3 next_normal;
    if (!normal_across(current, edge, normal, next_normal))
      return false;
    const auto next = static_cast<std::uint32_t>(neighbours_[current][edge]);
    if (next_normal.cross(side_normal).norm() > kFlat) {
      if (other_face >= 0 && next_normal.cross(other).norm() > kFlat)
        return false;  // a third normal: a cone of more than two faces
      if (other_face < 0) {
        other = next_normal;
        other_face = 2 * static_cast<int>(next) + seen_side(next, next_normal);
      }
    }
    if (next == slot) {
      if (other_face < 0)
        return false;
      out = {vertex, vertex, side_normal, other, face, other_face};
      return true;
    }
    const Triangle& triangle = bvh_->triangle(next);
    int at = 0;
    while (at < 3 && triangle.corner[at] != vertex)
      ++at;
    if (at == 3)
      return false;
    // The edge of `next` at the corner that does not lead back to `current`.
    edge = neighbours_[next][at] == static_cast<std::int32_t>(current) ? (at + 2) % 3 : at;
    current = next;
    normal = next_normal;
  }
  return false;
}

// 0 when `normal` is triangle `slot`'s own normal, 1 when it is turned over.
int MeshShellSurface::seen_side(std::uint32_t slot, const Vec3& normal) const {
  return bvh_->unit_normal(slot).dot(normal) < 0.0 ? 1 : 0;
}

}  // namespace partimix::geometry
