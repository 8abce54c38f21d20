#pragma once
// The nearest point on a set of triangles: exactly on one triangle, and through a bounding volume
// hierarchy over many, so that a query visits the few triangles near the point instead of all.
#include <Eigen/Geometry>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "core/vec.hpp"
#include "geometry/stl_reader.hpp"

namespace partimix::geometry {

// Where on its triangle a closest point lies: inside the face, inside edge k (from corner k to
// corner k + 1 mod 3) or on corner k. Inside-outside tests need it: the surface normal is
// defined on a face only, and edges and corners take a blend of their triangles' normals.
enum class TriangleFeature : std::uint8_t { kFace, kEdge, kCorner };

struct ClosestPoint {
  Vec3 point = Vec3::Zero();
  double distance_squared = 0.0;
  std::size_t triangle = 0;  // index in the triangles the hierarchy was built from
  TriangleFeature feature = TriangleFeature::kFace;
  int index = 0;           // the edge or corner, 0..2
  std::uint32_t slot = 0;  // index in the hierarchy's own order (TriangleBvh::closest_on)
};

// The closest point of a triangle to x (ClosestPoint::triangle left 0). Triangles of (nearly) no
// area are measured by their edges only.
ClosestPoint closest_point_on_triangle(const Triangle& triangle, const Vec3& x);

// A binary tree of axis-aligned boxes, split at the median of the triangle centroids along the
// longest axis, with a few triangles per leaf. Build O(n log n), query about O(log n) for points
// near the surface.
class TriangleBvh {
 public:
  TriangleBvh() = default;
  explicit TriangleBvh(const TriangleSoup& triangles);

  // The closest point to x over all triangles. Needs at least one triangle.
  ClosestPoint nearest(const Vec3& x) const;
  // The closest points of the triangles within `reach` of x, one per triangle, nearest first
  // (then by slot); the nearest out.size() when there are more. With `groups` (a group number
  // per slot), only the nearest triangle of each group. Returns their number. No allocation.
  int within(const Vec3& x, double reach, std::span<ClosestPoint> out,
             std::span<const std::int32_t> groups = {}) const;
  // The closest point to x on the triangle in `slot` alone, and that triangle and its unit
  // normal (zero for a sliver).
  ClosestPoint closest_on(std::uint32_t slot, const Vec3& x) const;
  const Triangle& triangle(std::uint32_t slot) const { return triangles_[slot]; }
  const Vec3& unit_normal(std::uint32_t slot) const { return unit_normals_[slot]; }
  std::size_t size() const { return triangles_.size(); }

 private:
  struct Node {
    Eigen::AlignedBox3d box;
    std::uint32_t first = 0;  // a leaf: its first triangle; an inner node: its first child
    std::uint32_t count = 0;  // a leaf: its number of triangles; an inner node: 0
  };

  void build(std::uint32_t node, std::uint32_t begin, std::uint32_t end,
             std::vector<Eigen::AlignedBox3d>& boxes);
  void visit_leaf(const Node& leaf, const Vec3& x, ClosestPoint& best) const;
  // Adds the leaf's triangles within sqrt(reach_squared) of x to the `count` sorted points.
  void gather_leaf(const Node& leaf, const Vec3& x, double reach_squared,
                   std::span<ClosestPoint> out, std::span<const std::int32_t> groups,
                   int& count) const;

  std::vector<Node> nodes_;
  std::vector<Triangle> triangles_;    // in leaf order
  std::vector<Vec3> unit_normals_;     // of the faces, zero for slivers
  std::vector<std::size_t> original_;  // leaf order -> index in the triangles given
};

}  // namespace partimix::geometry
