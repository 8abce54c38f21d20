#include "io/shape_section.hpp"

#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "core/error.hpp"
#include "geometry/cone.hpp"
#include "geometry/drum.hpp"
#include "geometry/plane.hpp"
#include "geometry/triangle_check.hpp"
#include "geometry/triangle_mesh.hpp"
#include "io/truck_drum_section.hpp"

namespace partimix::io {
namespace {

using ShapePtr = std::shared_ptr<const geometry::Shape>;

// In 2D every shape spans z in [-1, 1] m, so that the x-y plane lies inside it.
constexpr double kPlaneHalfThickness = 1.0;

void require_3d(const Reader& item, const std::string& shape, int dimensions) {
  if (dimensions != 3) {
    throw item.error("shape", fmt::format("{} needs dimensions: 3, this case has {}; "
                                          "in 2D: box, cylinder (a circle), plate (and plane "
                                          "for a wall)",
                                          shape, dimensions));
  }
}

ShapePtr read_box(Reader& item, int dimensions) {
  Vec3 lo = item.vector("min", dimensions);
  Vec3 hi = item.vector("max", dimensions);
  check_increasing(item, lo, hi, dimensions);
  if (dimensions == 2) {
    lo.z() = -kPlaneHalfThickness;
    hi.z() = kPlaneHalfThickness;
  }
  return std::make_shared<geometry::Box>(lo, hi);
}

// A cylinder about a z-parallel axis from its base centre up by `height`; in 2D a circle about
// `center` (the plane's z range, and `height` is an error).
ShapePtr read_cylinder(Reader& item, int dimensions) {
  Vec3 base_centre = item.vector("center", dimensions);
  const double radius = item.required<double>("radius", kPositive);
  if (dimensions == 2) {
    if (item.contains("height"))
      throw item.error("height", "applies to a cylinder in 3D only (in 2D it is a circle)");
    base_centre.z() = -kPlaneHalfThickness;
    return std::make_shared<geometry::Cylinder>(base_centre, radius, 2.0 * kPlaneHalfThickness);
  }
  const double height = item.required<double>("height", kPositive);
  return std::make_shared<geometry::Cylinder>(base_centre, radius, height);
}

// The z-range of a plate: in 3D from `clearance` above the floor at `bottom` up by `height`; in
// 2D the plane's range, and the 3D keys are errors.
std::pair<double, double> plate_z_range(Reader& item, int dimensions) {
  if (dimensions == 2) {
    for (const std::string key : {"height", "bottom", "clearance"}) {
      if (item.contains(key))
        throw item.error(key, "applies to a plate in 3D only (dimensions is 2)");
    }
    return {-kPlaneHalfThickness, kPlaneHalfThickness};
  }
  const double height = item.required<double>("height", kPositive);
  const double bottom = item.optional<double>("bottom", 0.0);
  const double clearance = item.optional<double>("clearance", 0.0, kNonNegative);
  return {bottom + clearance, bottom + clearance + height};
}

// A flat-plate impeller (the seed's section 2.1): `length` along x and `width` along y about
// `centre`, a point of the horizontal plane.
ShapePtr read_plate(Reader& item, int dimensions) {
  const Vec3 centre = item.vector("centre", 2);
  const double length = item.required<double>("length", kPositive);
  const double width = item.required<double>("width", kPositive);
  const auto [z_lo, z_hi] = plate_z_range(item, dimensions);
  const Vec3 half(0.5 * length, 0.5 * width, 0.0);
  Vec3 lo = centre - half;
  Vec3 hi = centre + half;
  lo.z() = z_lo;
  hi.z() = z_hi;
  return std::make_shared<geometry::Box>(lo, hi);
}

// A closed triangle mesh from an STL file (docs/geometry-meshes.md), scaled, then moved by
// `offset`.
ShapePtr read_mesh(Reader& item, int dimensions, const std::filesystem::path& case_folder) {
  MeshItem mesh = read_mesh_item(item, dimensions, case_folder);
  try {
    return std::make_shared<geometry::TriangleMesh>(std::move(mesh.triangles), Vec3::Zero());
  } catch (const InputError& error) {
    throw item.error("file",
                     fmt::format("cannot use the mesh: {}: {}", mesh.file, error.message()));
  }
}

// A plane through `point`; the material is on the side its normal points to.
ShapePtr read_plane(Reader& item, int dimensions) {
  const Vec3 normal = item.vector("normal", dimensions);
  if (normal.norm() == 0.0)
    throw item.error("normal", "the normal must not be the zero vector");
  return std::make_shared<geometry::Plane>(item.vector("point", dimensions), normal);
}

Vec3 read_axis(Reader& item) {
  const Vec3 axis = item.vector("axis", 3);
  if (axis.norm() == 0.0)
    throw item.error("axis", "the axis must not be the zero vector");
  return axis;
}

// The inside of an endless circular cylinder about `axis` through `axis_point`.
ShapePtr read_drum(Reader& item, int dimensions) {
  require_3d(item, "drum", dimensions);
  const Vec3 point = item.vector("axis_point", 3);
  const Vec3 axis = read_axis(item);
  return std::make_shared<geometry::Drum>(point, axis, item.required<double>("radius", kPositive));
}

// The inside of a cone frustum: radius_0 at axis_point, radius_1 `height` along the axis.
ShapePtr read_cone(Reader& item, int dimensions) {
  require_3d(item, "cone", dimensions);
  const Vec3 point = item.vector("axis_point", 3);
  const Vec3 axis = read_axis(item);
  const double radius_0 = item.required<double>("radius_0", kNonNegative);
  const double radius_1 = item.required<double>("radius_1", kNonNegative);
  const double height = item.required<double>("height", kPositive);
  if (radius_0 == 0.0 && radius_1 == 0.0)
    throw item.error("radius_1", "a cone needs radius_0 or radius_1 above 0");
  return std::make_shared<geometry::Cone>(point, axis, radius_0, radius_1, height);
}

}  // namespace

MeshItem read_mesh_item(Reader& item, int dimensions, const std::filesystem::path& case_folder) {
  require_3d(item, "mesh", dimensions);
  MeshItem mesh;
  mesh.file = item.required<std::string>("file");
  const double scale = item.optional<double>("scale", 1.0, kPositive);
  const Vec3 offset = item.vector("offset", 3, Vec3::Zero());
  const std::string path = (case_folder / mesh.file).string();
  try {
    mesh.triangles = geometry::read_stl(path, scale);
  } catch (const InputError& error) {
    throw item.error("file", fmt::format("cannot use the mesh: {}", error.what()));
  }
  try {
    mesh.triangles = geometry::checked_triangles(std::move(mesh.triangles), offset);
  } catch (const InputError& error) {
    throw item.error("file", fmt::format("cannot use the mesh {}: {}", path, error.message()));
  }
  return mesh;
}

ShapePtr read_shape(Reader& item, int dimensions, const std::filesystem::path& case_folder) {
  const std::string shape =
      item.required_choice("shape", {"box", "cylinder", "plate", "mesh", "truck_drum"});
  return read_shape_of(shape, item, dimensions, case_folder);
}

ShapePtr read_shape_of(const std::string& shape, Reader& item, int dimensions,
                       const std::filesystem::path& case_folder) {
  if (shape == "cylinder")
    return read_cylinder(item, dimensions);
  if (shape == "plate")
    return read_plate(item, dimensions);
  if (shape == "mesh")
    return read_mesh(item, dimensions, case_folder);
  if (shape == "plane")
    return read_plane(item, dimensions);
  if (shape == "drum")
    return read_drum(item, dimensions);
  if (shape == "cone")
    return read_cone(item, dimensions);
  if (shape == "truck_drum")
    return read_truck_drum(item, dimensions);
  return read_box(item, dimensions);
}

void check_increasing(const Reader& reader, const Vec3& lo, const Vec3& hi, int dimensions) {
  for (int axis = 0; axis < dimensions; ++axis) {
    if (!(hi[axis] > lo[axis])) {
      throw reader.error("max", fmt::format("must be > min on every axis; {}: max {} <= min {}",
                                            "xyz"[axis], hi[axis], lo[axis]));
    }
  }
}

}  // namespace partimix::io
