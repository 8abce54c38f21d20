#include "geometry/triangle_bvh.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <numeric>

namespace partimix::geometry {
namespace {

constexpr std::uint32_t kLeafSize = 4;

// A triangle whose doubled area is below this fraction of its summed squared edge lengths
// (about 0.29 for an equilateral one) has no reliable normal, so its face is not projected on.
constexpr double kSliver = 1e-12;

// True when x projects onto the inside (or boundary) of the triangle's face: x lies on the
// inner side of each edge, measured along the face normal.
bool projects_inside(const Triangle& triangle, const Vec3& normal, const Vec3& x) {
  const auto& c = triangle.corner;
  for (int k = 0; k < 3; ++k) {
    const Vec3 edge = c[(k + 1) % 3] - c[k];
    if (edge.cross(x - c[k]).dot(normal) < 0.0) {
      return false;
    }
  }
  return true;
}

bool is_sliver(const Triangle& triangle, const Vec3& normal) {
  const auto& c = triangle.corner;
  const double edges_squared =
      (c[1] - c[0]).squaredNorm() + (c[2] - c[1]).squaredNorm() + (c[0] - c[2]).squaredNorm();
  return normal.norm() <= kSliver * edges_squared;
}

// The unit normal of the face, or zero for a sliver.
Vec3 face_unit_normal(const Triangle& triangle) {
  const auto& c = triangle.corner;
  const Vec3 normal = (c[1] - c[0]).cross(c[2] - c[0]);
  return is_sliver(triangle, normal) ? Vec3(Vec3::Zero()) : Vec3(normal.normalized());
}

ClosestPoint closest_point_on_edge(const Triangle& triangle, int k, const Vec3& x) {
  const Vec3& a = triangle.corner[k];
  const Vec3& b = triangle.corner[(k + 1) % 3];
  const Vec3 ab = b - a;
  const double length_squared = ab.squaredNorm();
  const double s = length_squared > 0.0 ? (x - a).dot(ab) / length_squared : 0.0;
  ClosestPoint closest;
  if (s <= 0.0) {
    closest.point = a;
    closest.feature = TriangleFeature::kCorner;
    closest.index = k;
  } else if (s >= 1.0) {
    closest.point = b;
    closest.feature = TriangleFeature::kCorner;
    closest.index = (k + 1) % 3;
  } else {
    closest.point = a + s * ab;
    closest.feature = TriangleFeature::kEdge;
    closest.index = k;
  }
  closest.distance_squared = (x - closest.point).squaredNorm();
  return closest;
}

ClosestPoint closest_point_on_boundary(const Triangle& triangle, const Vec3& x) {
  ClosestPoint best = closest_point_on_edge(triangle, 0, x);
  for (int k = 1; k < 3; ++k) {
    const ClosestPoint candidate = closest_point_on_edge(triangle, k, x);
    if (candidate.distance_squared < best.distance_squared) {
      best = candidate;
    }
  }
  return best;
}

// With the face's unit normal given (zero for a sliver), so that a hierarchy computes it once.
ClosestPoint closest_point(const Triangle& triangle, const Vec3& unit_normal, const Vec3& x) {
  if (unit_normal.squaredNorm() == 0.0 || !projects_inside(triangle, unit_normal, x)) {
    return closest_point_on_boundary(triangle, x);
  }
  const double height = (x - triangle.corner[0]).dot(unit_normal);
  ClosestPoint closest;
  closest.point = x - height * unit_normal;
  closest.distance_squared = height * height;
  closest.feature = TriangleFeature::kFace;
  return closest;
}

// Zero inside the box. Branch-free, unlike Eigen's squaredExteriorDistance: the traversal spends
// most of its time here, on boxes whose side of x is unpredictable.
double squared_distance_to_box(const Eigen::AlignedBox3d& box, const Vec3& x) {
  return (box.min() - x).cwiseMax(x - box.max()).cwiseMax(0.0).squaredNorm();
}

// Nearest first, then by slot: a strict total order, independent of the traversal.
bool precedes(const ClosestPoint& a, const ClosestPoint& b) {
  return a.distance_squared < b.distance_squared ||
         (a.distance_squared == b.distance_squared && a.slot < b.slot);
}

// Inserts `point` into the sorted first `count` entries of `out`, the last falling off when full.
void insert_sorted(const ClosestPoint& point, std::span<ClosestPoint> out, int& count) {
  int k = count < static_cast<int>(out.size()) ? count++ : count - 1;
  while (k > 0 && precedes(point, out[k - 1])) {
    out[k] = out[k - 1];
    --k;
  }
  out[k] = point;
}

// Drops entry k of the first `count` entries of `out`.
void erase_at(std::span<ClosestPoint> out, int k, int& count) {
  for (int j = k + 1; j < count; ++j)
    out[j - 1] = out[j];
  --count;
}

Eigen::AlignedBox3d box_of(const Triangle& triangle) {
  Eigen::AlignedBox3d box(triangle.corner[0]);
  box.extend(triangle.corner[1]);
  box.extend(triangle.corner[2]);
  return box;
}

}  // namespace

ClosestPoint closest_point_on_triangle(const Triangle& triangle, const Vec3& x) {
  return closest_point(triangle, face_unit_normal(triangle), x);
}

TriangleBvh::TriangleBvh(const TriangleSoup& triangles) : original_(triangles.size()) {
  if (triangles.empty()) {
    return;
  }
  std::iota(original_.begin(), original_.end(), std::size_t{0});
  std::vector<Eigen::AlignedBox3d> boxes;
  boxes.reserve(triangles.size());
  for (const Triangle& triangle : triangles) {
    boxes.push_back(box_of(triangle));
  }
  nodes_.reserve(2 * triangles.size() / kLeafSize + 1);
  nodes_.emplace_back();
  build(0, 0, static_cast<std::uint32_t>(triangles.size()), boxes);
  triangles_.reserve(triangles.size());
  unit_normals_.reserve(triangles.size());
  for (std::size_t i : original_) {
    triangles_.push_back(triangles[i]);
    unit_normals_.push_back(face_unit_normal(triangles[i]));
  }
}

// Fills node `node` with the triangles original_[begin, end), reordering them so that each
// child holds a contiguous half.
void TriangleBvh::build(std::uint32_t node, std::uint32_t begin, std::uint32_t end,
                        std::vector<Eigen::AlignedBox3d>& boxes) {
  Eigen::AlignedBox3d box;
  Eigen::AlignedBox3d centres;
  for (std::uint32_t i = begin; i < end; ++i) {
    box.extend(boxes[original_[i]]);
    centres.extend(boxes[original_[i]].center());
  }
  nodes_[node].box = box;
  if (end - begin <= kLeafSize) {
    nodes_[node].first = begin;
    nodes_[node].count = end - begin;
    return;
  }
  Eigen::Index axis = 0;
  centres.sizes().maxCoeff(&axis);
  const std::uint32_t middle = begin + (end - begin) / 2;
  std::nth_element(original_.begin() + begin, original_.begin() + middle, original_.begin() + end,
                   [&](std::size_t a, std::size_t b) {
                     return boxes[a].center()[axis] < boxes[b].center()[axis];
                   });
  const auto child = static_cast<std::uint32_t>(nodes_.size());
  nodes_[node].first = child;
  nodes_.resize(nodes_.size() + 2);
  build(child, begin, middle, boxes);
  build(child + 1, middle, end, boxes);
}

// A triangle's plane is never farther than the triangle itself: one dot product rules out most
// triangles of a leaf before the full closest-point computation.
void TriangleBvh::visit_leaf(const Node& leaf, const Vec3& x, ClosestPoint& best) const {
  for (std::uint32_t i = leaf.first; i < leaf.first + leaf.count; ++i) {
    const double height = (x - triangles_[i].corner[0]).dot(unit_normals_[i]);
    if (height * height >= best.distance_squared) {
      continue;
    }
    ClosestPoint candidate = closest_point(triangles_[i], unit_normals_[i], x);
    if (candidate.distance_squared < best.distance_squared) {
      candidate.triangle = original_[i];
      candidate.slot = i;
      best = candidate;
    }
  }
}

ClosestPoint TriangleBvh::closest_on(std::uint32_t slot, const Vec3& x) const {
  ClosestPoint closest = closest_point(triangles_[slot], unit_normals_[slot], x);
  closest.triangle = original_[slot];
  closest.slot = slot;
  return closest;
}

void TriangleBvh::gather_leaf(const Node& leaf, const Vec3& x, double reach_squared,
                              std::span<ClosestPoint> out, std::span<const std::int32_t> groups,
                              int& count) const {
  const int capacity = static_cast<int>(out.size());
  for (std::uint32_t i = leaf.first; i < leaf.first + leaf.count; ++i) {
    const double height = (x - triangles_[i].corner[0]).dot(unit_normals_[i]);
    if (height * height > reach_squared)
      continue;
    const ClosestPoint candidate = closest_on(i, x);
    if (candidate.distance_squared > reach_squared)
      continue;
    if (!groups.empty()) {
      const auto same = std::find_if(out.begin(), out.begin() + count, [&](const ClosestPoint& p) {
        return groups[p.slot] == groups[i];
      });
      if (same != out.begin() + count) {
        if (!precedes(candidate, *same))
          continue;
        erase_at(out, static_cast<int>(same - out.begin()), count);
      }
    }
    if (count == capacity && !precedes(candidate, out[count - 1]))
      continue;
    insert_sorted(candidate, out, count);
  }
}

int TriangleBvh::within(const Vec3& x, double reach, std::span<ClosestPoint> out,
                        std::span<const std::int32_t> groups) const {
  if (nodes_.empty() || out.empty())
    return 0;
  const double reach_squared = reach * reach;
  int count = 0;
  std::array<std::uint32_t, 64> stack{};
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    if (squared_distance_to_box(node.box, x) > reach_squared)
      continue;
    if (node.count > 0) {
      gather_leaf(node, x, reach_squared, out, groups, count);
      continue;
    }
    stack[top++] = node.first + 1;
    stack[top++] = node.first;
  }
  return count;
}

// Depth first, nearer child first, skipping every box farther than the best point found so far.
ClosestPoint TriangleBvh::nearest(const Vec3& x) const {
  ClosestPoint best;
  best.distance_squared = std::numeric_limits<double>::infinity();
  if (nodes_.empty()) {
    return best;
  }
  struct Pending {
    std::uint32_t node;
    double distance_squared;
  };
  // Median splits keep the depth below 33 for any uint32 count; one pending sibling per level.
  std::array<Pending, 64> stack{};
  int top = 0;
  stack[top++] = {0, squared_distance_to_box(nodes_[0].box, x)};
  while (top > 0) {
    const Pending pending = stack[--top];
    if (pending.distance_squared >= best.distance_squared) {
      continue;
    }
    const Node& node = nodes_[pending.node];
    if (node.count > 0) {
      visit_leaf(node, x, best);
      continue;
    }
    Pending nearer{node.first, squared_distance_to_box(nodes_[node.first].box, x)};
    Pending farther{node.first + 1, squared_distance_to_box(nodes_[node.first + 1].box, x)};
    if (farther.distance_squared < nearer.distance_squared) {
      std::swap(nearer, farther);
    }
    stack[top++] = farther;
    stack[top++] = nearer;
  }
  return best;
}

}  // namespace partimix::geometry
