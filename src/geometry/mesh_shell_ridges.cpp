// The convex edges and corners of a mesh shell (docs/dem.md, "Walls and superquadrics", Convex
// edges and corners): where a superquadric grain meets the solid behind several faces at once.
#include <algorithm>
#include <array>

#include "geometry/mesh_shell_surface.hpp"

namespace partimix::geometry {

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

// A convex edge, or a corner whose triangles (walked across the edges that meet there) meet at
// convex or flat edges only: a convex corner, with the distinct normals in the walk's order (two
// for a corner along a straight ridge). Each normal's face is the first triangle met with it;
// all of them hold the edge or corner, so shadowed() keeps a contact there once.
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
  out.normals[0] = side_normal;
  out.faces[0] = at.face;
  out.count = 1;
  if (count == 2) {  // edges k and k + 1 meet at corner k + 1; edges 0 and 2 at corner 0
    const int corner = on[1] == on[0] + 1 ? on[1] : on[0];
    out.start = out.end = triangle.corner[corner];
    return convex_corner(slot, corner, out);
  }
  const int k = on[0];
  Vec3 other;
  if (bend(slot, k, side_normal) != Bend::kConvex || !normal_across(slot, k, side_normal, other))
    return false;
  const auto neighbour = static_cast<std::uint32_t>(neighbours_[slot][k]);
  out.start = triangle.corner[k];
  out.end = triangle.corner[(k + 1) % 3];
  out.normals[1] = other;
  out.faces[1] = 2 * static_cast<int>(neighbour) + seen_side(neighbour, other);
  out.count = 2;
  return true;
}

// Around corner `corner` of triangle `slot` (out holds its normal): each step crosses the other
// edge of the current triangle that meets at the corner, adding each normal that differs from the
// last one added.
bool MeshShellSurface::convex_corner(std::uint32_t slot, int corner, Ridge& out) const {
  const auto differs = [](const Vec3& a, const Vec3& b) { return a.cross(b).norm() > kFlat; };
  std::uint32_t current = slot;
  Vec3 normal = out.normals[0];
  int edge = corner;  // edges corner and corner + 2 meet at the corner
  for (int step = 0; step < kWalk; ++step) {
    Vec3 next_normal;
    if (!normal_across(current, edge, normal, next_normal))
      return false;
    const auto next = static_cast<std::uint32_t>(neighbours_[current][edge]);
    if (next == slot) {
      if (out.count > 2 && !differs(out.normals[out.count - 1], out.normals[0]))
        --out.count;  // the walk began inside a run of triangles of one normal
      return out.count >= 2;
    }
    if (differs(next_normal, out.normals[out.count - 1])) {
      if (out.count == Ridge::kMaxFaces)
        return false;
      out.normals[out.count] = next_normal;
      out.faces[out.count++] = 2 * static_cast<int>(next) + seen_side(next, next_normal);
    }
    const Triangle& triangle = bvh_->triangle(next);
    int at = 0;
    while (at < 3 && triangle.corner[at] != out.start)
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

// The side of its flat part that a face is on: 2 part + 0 on the side of the normal of the
// part's first triangle (the part's number), + 1 behind it.
int MeshShellSurface::part_side(int face) const {
  const auto slot = static_cast<std::uint32_t>(face / 2);
  const std::int32_t part = parts_[slot];
  const double facing =
      bvh_->unit_normal(slot).dot(bvh_->unit_normal(static_cast<std::uint32_t>(part)));
  const bool behind = (face % 2 == 0) == (facing < 0.0);
  return 2 * part + (behind ? 1 : 0);
}

// The face of triangle `slot` on the side `side` (a part_side() of slot's part).
int MeshShellSurface::face_on_side(std::uint32_t slot, int side) const {
  const int face = 2 * static_cast<int>(slot);
  return part_side(face) == side ? face : face + 1;
}

// Each edge between two flat parts that is convex seen from a side of one gives the pair of
// sides (sorted, once).
void MeshShellSurface::find_convex_neighbours() {
  convex_pairs_.clear();
  for (std::uint32_t slot = 0; slot < bvh_->size(); ++slot) {
    for (int k = 0; k < 3; ++k) {
      const std::int32_t other = neighbours_[slot][k];
      if (other < 0 || parts_[static_cast<std::size_t>(other)] == parts_[slot])
        continue;
      const auto neighbour = static_cast<std::uint32_t>(other);
      for (const int side : {0, 1}) {
        const Vec3 side_normal = (side == 0 ? 1.0 : -1.0) * bvh_->unit_normal(slot);
        Vec3 across;
        if (bend(slot, k, side_normal) != Bend::kConvex ||
            !normal_across(slot, k, side_normal, across))
          continue;
        const int a = part_side(2 * static_cast<int>(slot) + side);
        const int b = part_side(2 * static_cast<int>(neighbour) + seen_side(neighbour, across));
        convex_pairs_.emplace_back(std::min(a, b), std::max(a, b));
      }
    }
  }
  std::sort(convex_pairs_.begin(), convex_pairs_.end());
  convex_pairs_.erase(std::unique(convex_pairs_.begin(), convex_pairs_.end()), convex_pairs_.end());
}

bool MeshShellSurface::convex_neighbours(int face_a, int face_b) const {
  const int a = part_side(face_a);
  const int b = part_side(face_b);
  return std::binary_search(convex_pairs_.begin(), convex_pairs_.end(),
                            std::pair{std::min(a, b), std::max(a, b)});
}

// The triangles of face's part within reach, nearest first: each convex edge (seen from the
// face's side) as a segment, and each corner of such an edge that is a convex corner of three or
// more normals, once.
int MeshShellSurface::ridges_near(int face, const Vec3& centre, double reach,
                                  std::span<Ridge> out) const {
  if (out.empty() || !near_box(centre, reach))
    return 0;
  std::array<ClosestPoint, kCandidates> near;
  const int found = bvh_->within(centre, reach, near);
  const int side = part_side(face);
  int count = 0;
  const auto add = [&](const Ridge& ridge) {
    for (int k = 0; k < count; ++k) {
      if (out[k].count == ridge.count && out[k].start == ridge.start && out[k].end == ridge.end)
        return;
    }
    if (count < static_cast<int>(out.size()))
      out[count++] = ridge;
  };
  for (int n = 0; n < found; ++n) {
    const std::uint32_t slot = near[n].slot;
    if (parts_[slot] != side / 2)
      continue;
    const int own = face_on_side(slot, side);
    const Vec3 side_normal = (own % 2 == 0 ? 1.0 : -1.0) * bvh_->unit_normal(slot);
    const Triangle& triangle = bvh_->triangle(slot);
    for (int k = 0; k < 3; ++k) {
      Ridge edge;
      if (bend(slot, k, side_normal) != Bend::kConvex ||
          !normal_across(slot, k, side_normal, edge.normals[1]))
        continue;
      const auto neighbour = static_cast<std::uint32_t>(neighbours_[slot][k]);
      edge.start = triangle.corner[k];
      edge.end = triangle.corner[(k + 1) % 3];
      edge.normals[0] = side_normal;
      edge.faces = {own, 2 * static_cast<int>(neighbour) + seen_side(neighbour, edge.normals[1])};
      edge.count = 2;
      add(edge);
      for (const int corner : {k, (k + 1) % 3}) {
        Ridge cone;
        cone.start = cone.end = triangle.corner[corner];
        cone.normals[0] = side_normal;
        cone.faces[0] = own;
        cone.count = 1;
        if (convex_corner(slot, corner, cone) && cone.count > 2)
          add(cone);
      }
    }
  }
  return count;
}

}  // namespace partimix::geometry
