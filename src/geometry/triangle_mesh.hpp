#pragma once
// A closed triangle mesh (an impeller, a baffle, a vessel from CAD) as a Shape.
//
// Magnitude: the exact distance to the nearest triangle, found through a bounding volume
// hierarchy. Sign: the angle-weighted pseudo-normal of the nearest feature (Baerentzen and
// Aanaes 2005): the face normal when the nearest point lies inside a face, the sum of the two
// face normals on an edge, and the sum of the face normals weighted by their angles at a corner.
// For a closed, consistently oriented 2-manifold, x lies outside exactly when (x - nearest point)
// points along that pseudo-normal, at any distance. It is chosen over the generalised winding
// number because the nearest-point query has already found the feature, so the sign costs one
// dot product, while a winding number sums a solid angle over every triangle (or needs a
// second, approximate, hierarchical pass); the price is that the mesh must be closed and
// consistently oriented, which the constructor checks.
#include <array>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "core/vec.hpp"
#include "geometry/shape.hpp"
#include "geometry/stl_reader.hpp"
#include "geometry/triangle_bvh.hpp"

namespace partimix::geometry {

// The pseudo-normals of one triangle's features, as in TriangleFeature.
struct PseudoNormals {
  Vec3 face = Vec3::Zero();
  std::array<Vec3, 3> edge{Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
  std::array<Vec3, 3> corner{Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
};

class TriangleMesh final : public Shape {
 public:
  // The triangles moved by `translation`. Corners with bit-identical coordinates are joined;
  // triangles with two joined corners are dropped; a mesh wound inside out is turned over.
  // Throws InputError (no file or key path: the caller knows them) when no triangle is left,
  // when an edge does not belong to exactly two triangles that run it in opposite directions
  // (a hole, a non-manifold edge, inconsistent orientation), or when the mesh encloses no volume.
  explicit TriangleMesh(TriangleSoup triangles, const Vec3& translation = Vec3::Zero());

  double signed_distance(const Vec3& x) const override;
  Vec3 lower() const override { return lower_; }
  Vec3 upper() const override { return upper_; }
  // A two-sided MeshShellSurface over the same triangles, sharing the hierarchy, whatever
  // `solid` and `open_faces` say (a mesh has no faces to open; DEM contacts it from both sides).
  std::unique_ptr<Surface> make_surface(bool solid,
                                        const std::vector<Face>& open_faces) const override;
  std::size_t triangle_count() const { return bvh_->size(); }

 private:
  std::shared_ptr<const TriangleBvh> bvh_;  // shared with the surfaces made from the mesh
  std::vector<PseudoNormals> normals_;      // by triangle index in the hierarchy's input
  Vec3 lower_ = Vec3::Zero();
  Vec3 upper_ = Vec3::Zero();
};

// The mesh of the STL file at `path` (read_stl), scaled, then moved by `translation`. Every
// InputError, the mesh's own included, names the file.
TriangleMesh read_triangle_mesh(const std::string& path, double scale = 1.0,
                                const Vec3& translation = Vec3::Zero());

}  // namespace partimix::geometry
