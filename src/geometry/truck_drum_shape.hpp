#pragma once
// The truck drum as a wall (docs/truck-drum.md, "As a wall"): the drum of truck_drum.hpp placed
// in the case by the centre of its closed head (`axis_point`) and its axis towards the opening,
// its own frame turned onto the case's by the smallest rotation that takes z to the axis (so the
// offset angles count from the image of the case's x). Signed distance: the drum's cavity less
// the blades, negative where the material goes; beyond the opening's plane lies its open end (no
// wall layers). Contact surface: one two-sided MeshShellSurface over the shell, open at the
// opening, and the six blades sunk into the wall behind it (truck_drum_surface_mesh), whose
// triangles are also the STL the `stl` command writes.
#include <memory>
#include <vector>

#include "core/vec.hpp"
#include "geometry/shape.hpp"
#include "geometry/stl_reader.hpp"
#include "geometry/truck_drum.hpp"

namespace partimix::geometry {

class TruckDrumShape final : public Shape {
 public:
  // `divisions`: the points around each ring of the surface's mesh (truck_drum_mesh.hpp). Throws
  // std::invalid_argument as TruckDrumGeometry does, or for a zero axis.
  TruckDrumShape(const TruckDrumParameters& parameters, const Vec3& axis_point, const Vec3& axis,
                 int divisions);

  double signed_distance(const Vec3& x) const override;
  Vec3 lower() const override { return lower_; }
  Vec3 upper() const override { return upper_; }
  bool beyond_open_end(const Vec3& x, const std::vector<Face>& open_faces) const override;
  // The surface of the drum's triangles, whatever `solid` and `open_faces` say.
  std::unique_ptr<Surface> make_surface(bool solid,
                                        const std::vector<Face>& open_faces) const override;
  TriangleSoup triangles() const override { return triangles_; }
  // Outside the shell and short of the opening's plane, or within half a cell of a blade: a blade
  // thinner than a cell still blocks the cells it crosses (docs/truck-drum.md, "On a grid").
  std::optional<bool> blocks_grid_cell(const Vec3& x, double cell) const override;

  // x of the case in the drum's own frame, and back.
  Vec3 to_drum(const Vec3& x) const { return rotation_.transpose() * (x - axis_point_); }
  Vec3 from_drum(const Vec3& local) const { return axis_point_ + rotation_ * local; }
  const TruckDrumGeometry& drum() const { return drum_; }

 private:
  TruckDrumGeometry drum_;
  Vec3 axis_point_;
  Mat3 rotation_;  // columns: the drum's x, y and z (the axis) in the case's frame
  TriangleSoup triangles_;
  Vec3 lower_;
  Vec3 upper_;
};

}  // namespace partimix::geometry
