#include "geometry/triangle_mesh.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <string>
#include <utility>

#include "core/error.hpp"
#include "geometry/mesh_shell_surface.hpp"

namespace partimix::geometry {
namespace {

using VertexId = std::uint32_t;
using EdgeKey = std::pair<VertexId, VertexId>;  // from, to

// The triangles with their corners numbered, equal coordinates getting equal numbers: STL
// stores every corner once per triangle, and the edges and corners that triangles share are
// what closure, orientation and pseudo-normals are about.
struct WeldedSurface {
  TriangleSoup triangles;
  std::vector<std::array<VertexId, 3>> corners;
  std::vector<Vec3> vertices;
};

InputError mesh_error(const std::string& message) {
  return InputError(InputLocation{}, "triangle mesh: " + message);
}

std::string describe(const Vec3& x) {
  return fmt::format("({}, {}, {})", x.x(), x.y(), x.z());
}

void translate_and_check(TriangleSoup& triangles, const Vec3& translation) {
  for (Triangle& triangle : triangles) {
    for (Vec3& corner : triangle.corner) {
      corner += translation;
      if (!corner.allFinite()) {
        throw mesh_error("a corner coordinate is not a finite number");
      }
    }
  }
}

bool collapsed(const std::array<VertexId, 3>& c) {
  return c[0] == c[1] || c[1] == c[2] || c[2] == c[0];
}

// Triangles with two equal corners have no area and would count as extra edge owners.
WeldedSurface weld(const TriangleSoup& triangles) {
  WeldedSurface surface;
  std::map<std::array<double, 3>, VertexId> ids;
  const auto id_of = [&](const Vec3& x) {
    const auto next = static_cast<VertexId>(surface.vertices.size());
    const auto [it, inserted] = ids.try_emplace({x.x(), x.y(), x.z()}, next);
    if (inserted) {
      surface.vertices.push_back(x);
    }
    return it->second;
  };
  for (const Triangle& triangle : triangles) {
    const std::array<VertexId, 3> corners{id_of(triangle.corner[0]), id_of(triangle.corner[1]),
                                          id_of(triangle.corner[2])};
    if (!collapsed(corners)) {
      surface.triangles.push_back(triangle);
      surface.corners.push_back(corners);
    }
  }
  return surface;
}

std::map<EdgeKey, int> directed_edge_counts(const WeldedSurface& surface) {
  std::map<EdgeKey, int> counts;
  for (const auto& c : surface.corners) {
    for (int k = 0; k < 3; ++k) {
      ++counts[{c[k], c[(k + 1) % 3]}];
    }
  }
  return counts;
}

std::string edge_problem(const WeldedSurface& surface, const EdgeKey& edge, int owners,
                         int same_way) {
  const std::string where =
      fmt::format("the edge from {} to {}", describe(surface.vertices[edge.first]),
                  describe(surface.vertices[edge.second]));
  if (owners == 1) {
    return "it is not closed: " + where + " belongs to one triangle only";
  }
  if (owners > 2) {
    return fmt::format("it is not a 2-manifold: {} belongs to {} triangles", where, owners);
  }
  return fmt::format("its triangles are not consistently oriented: {} run {} the same way",
                     same_way, where);
}

// Closed and consistently oriented: every edge is run once each way.
void check_closed(const WeldedSurface& surface) {
  const std::map<EdgeKey, int> counts = directed_edge_counts(surface);
  for (const auto& [edge, forward] : counts) {
    const auto reverse = counts.find({edge.second, edge.first});
    const int backward = reverse == counts.end() ? 0 : reverse->second;
    if (forward != 1 || backward != 1) {
      throw mesh_error(
          edge_problem(surface, edge, forward + backward, std::max(forward, backward)));
    }
  }
}

// Six times the signed volume, measured from the first vertex rather than the origin so that a
// mesh far from the origin loses no digits.
double six_times_volume(const WeldedSurface& surface) {
  const Vec3& origin = surface.vertices.front();
  double sum = 0.0;
  for (const Triangle& t : surface.triangles) {
    const auto& c = t.corner;
    sum += (c[0] - origin).dot((c[1] - origin).cross(c[2] - origin));
  }
  return sum;
}

Eigen::AlignedBox3d bounds_of(const TriangleSoup& triangles) {
  Eigen::AlignedBox3d box;
  for (const Triangle& t : triangles) {
    for (const Vec3& corner : t.corner) {
      box.extend(corner);
    }
  }
  return box;
}

// Turns an inside-out mesh (corners clockwise seen from outside) the right way round.
void orient_outward(WeldedSurface& surface) {
  const double volume6 = six_times_volume(surface);
  const double size = bounds_of(surface.triangles).sizes().maxCoeff();
  if (!(std::abs(volume6) > 1e-12 * size * size * size)) {
    throw mesh_error("it encloses no volume");
  }
  if (volume6 < 0.0) {
    for (std::size_t t = 0; t < surface.triangles.size(); ++t) {
      std::swap(surface.triangles[t].corner[1], surface.triangles[t].corner[2]);
      std::swap(surface.corners[t][1], surface.corners[t][2]);
    }
  }
}

Vec3 unit_normal(const Triangle& triangle) {
  const auto& c = triangle.corner;
  const Vec3 normal = (c[1] - c[0]).cross(c[2] - c[0]);
  const double length = normal.norm();
  return length > 0.0 ? Vec3(normal / length) : Vec3(Vec3::Zero());
}

double corner_angle(const Triangle& triangle, int k) {
  const auto& c = triangle.corner;
  const Vec3 a = c[(k + 1) % 3] - c[k];
  const Vec3 b = c[(k + 2) % 3] - c[k];
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

EdgeKey undirected(VertexId a, VertexId b) {
  return {std::min(a, b), std::max(a, b)};
}

// The edge pseudo-normal is the plain sum of its two face normals (each weighted by the same
// angle, pi); the corner pseudo-normal weights each face normal by its angle at the corner.
std::vector<PseudoNormals> pseudo_normals(const WeldedSurface& surface) {
  const std::size_t n = surface.triangles.size();
  std::vector<PseudoNormals> normals(n);
  std::vector<Vec3> corner_sums(surface.vertices.size(), Vec3::Zero());
  std::map<EdgeKey, Vec3> edge_sums;
  for (std::size_t t = 0; t < n; ++t) {
    const Vec3 face = unit_normal(surface.triangles[t]);
    normals[t].face = face;
    const auto& c = surface.corners[t];
    for (int k = 0; k < 3; ++k) {
      corner_sums[c[k]] += corner_angle(surface.triangles[t], k) * face;
      edge_sums.try_emplace(undirected(c[k], c[(k + 1) % 3]), Vec3::Zero()).first->second += face;
    }
  }
  for (std::size_t t = 0; t < n; ++t) {
    const auto& c = surface.corners[t];
    for (int k = 0; k < 3; ++k) {
      normals[t].corner[k] = corner_sums[c[k]];
      normals[t].edge[k] = edge_sums.at(undirected(c[k], c[(k + 1) % 3]));
    }
  }
  return normals;
}

const Vec3& pseudo_normal(const PseudoNormals& normals, const ClosestPoint& nearest) {
  switch (nearest.feature) {
    case TriangleFeature::kEdge:
      return normals.edge[nearest.index];
    case TriangleFeature::kCorner:
      return normals.corner[nearest.index];
    case TriangleFeature::kFace:
      break;
  }
  return normals.face;
}

}  // namespace

TriangleMesh::TriangleMesh(TriangleSoup triangles, const Vec3& translation) {
  translate_and_check(triangles, translation);
  WeldedSurface surface = weld(triangles);
  if (surface.triangles.empty()) {
    throw mesh_error("it has no triangle with three distinct corners");
  }
  check_closed(surface);
  orient_outward(surface);
  normals_ = pseudo_normals(surface);
  const Eigen::AlignedBox3d bounds = bounds_of(surface.triangles);
  lower_ = bounds.min();
  upper_ = bounds.max();
  bvh_ = std::make_shared<const TriangleBvh>(surface.triangles);
}

double TriangleMesh::signed_distance(const Vec3& x) const {
  const ClosestPoint nearest = bvh_->nearest(x);
  const double distance = std::sqrt(nearest.distance_squared);
  const double side = (x - nearest.point).dot(pseudo_normal(normals_[nearest.triangle], nearest));
  return side < 0.0 ? -distance : distance;
}

std::unique_ptr<Surface> TriangleMesh::make_surface(bool /*solid*/,
                                                    const std::vector<Face>& /*open_faces*/) const {
  return std::make_unique<MeshShellSurface>(bvh_, lower_, upper_);
}

TriangleMesh read_triangle_mesh(const std::string& path, double scale, const Vec3& translation) {
  TriangleSoup triangles = read_stl(path, scale);
  try {
    return TriangleMesh(std::move(triangles), translation);
  } catch (const InputError& error) {
    throw InputError(InputLocation{path, 0, 0, error.location().key_path}, error.message());
  }
}

}  // namespace partimix::geometry
