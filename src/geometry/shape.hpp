#pragma once
// Shapes known by their signed distance (negative inside) and bounding box. Lattice samplers fill
// a shape or lay wall layers around it from these two alone, so any new shape gets both. A shape
// also makes its contact surface (surface.hpp), so that one wall serves SPH, which lays
// particles from the signed distance, and DEM, which contacts the surface: on the surface's
// closed parts the two agree (|gap| = |signed distance| near the surface).
#include <memory>
#include <optional>
#include <vector>

#include "core/vec.hpp"
#include "geometry/face.hpp"
#include "geometry/stl_reader.hpp"
#include "geometry/surface.hpp"

namespace partimix::geometry {

class Shape {
 public:
  virtual ~Shape() = default;
  virtual double signed_distance(const Vec3& x) const = 0;
  // The bounding box; a bound may be -/+infinity where the shape has no end (a plane, a drum).
  virtual Vec3 lower() const = 0;
  virtual Vec3 upper() const = 0;
  // Whether x lies beyond an open end of the shape as a container, where it gets no wall layers
  // (lattice.hpp). By default: beyond one of `open_faces` of the bounding box.
  virtual bool beyond_open_end(const Vec3& x, const std::vector<Face>& open_faces) const;
  // The shape's contact surface as a wall, in the same frame: with `solid` the material is
  // outside the shape (an impeller), otherwise inside it (a container) with `open_faces` left
  // open. Shapes that are always one or the other (plane, drum, cone, mesh) ignore both.
  virtual std::unique_ptr<Surface> make_surface(bool solid,
                                                const std::vector<Face>& open_faces) const = 0;
  // The triangles of a shape generated as a mesh (a truck drum), for the `stl` command; none for
  // the others.
  virtual TriangleSoup triangles() const { return {}; }
  // For a container whose contact surface is a shell with no behind (the truck drum's two-sided
  // mesh), whether a grid of cells `cell` wide blocks the cell centred at x; none for the others,
  // whose contact surface decides (cfd/blocked_cells.hpp).
  virtual std::optional<bool> blocks_grid_cell(const Vec3& /*x*/, double /*cell*/) const {
    return std::nullopt;
  }
};

// Axis-aligned box [lo, hi]. Its surface: a container with open faces
// (box_container_surface.hpp) or a solid box (solid_box_surface.hpp).
class Box final : public Shape {
 public:
  Box(const Vec3& lo, const Vec3& hi) : lo_(lo), hi_(hi) {}
  double signed_distance(const Vec3& x) const override;
  Vec3 lower() const override { return lo_; }
  Vec3 upper() const override { return hi_; }
  std::unique_ptr<Surface> make_surface(bool solid,
                                        const std::vector<Face>& open_faces) const override;

 private:
  Vec3 lo_;
  Vec3 hi_;
};

// Solid cylinder along z: base centre, radius, height. As a wall it is a vessel: side and
// bottom, with the top left open by the wall's open faces. Its surface: a vessel with its
// bottom or top open (cylinder_vessel_surface.hpp) or a solid cylinder
// (solid_cylinder_surface.hpp).
class Cylinder final : public Shape {
 public:
  Cylinder(const Vec3& base_centre, double radius, double height)
      : base_(base_centre), radius_(radius), height_(height) {}
  double signed_distance(const Vec3& x) const override;
  Vec3 lower() const override { return base_ - Vec3(radius_, radius_, 0.0); }
  Vec3 upper() const override { return base_ + Vec3(radius_, radius_, height_); }
  std::unique_ptr<Surface> make_surface(bool solid,
                                        const std::vector<Face>& open_faces) const override;

 private:
  Vec3 base_;
  double radius_;
  double height_;
};

}  // namespace partimix::geometry
