#include "io/walls_section.hpp"

#include <fmt/format.h>

#include "core/error.hpp"
#include "geometry/mesh_shell_surface.hpp"
#include "geometry/triangle_mesh.hpp"
#include "io/axis_names.hpp"
#include "io/motion_section.hpp"
#include "io/shape_section.hpp"

namespace partimix::io {
namespace {

const std::vector<std::string> kShapes{"box",   "cylinder", "plate", "mesh",
                                       "plane", "drum",     "cone",  "truck_drum"};

// Shapes that are one kind of wall only: a plane keeps the material on its normal's side, a drum
// and a cone hold it inside with their ends open, a truck drum inside with its opening open.
bool has_fixed_side(const std::string& kind) {
  return kind == "plane" || kind == "drum" || kind == "cone" || kind == "truck_drum";
}

std::vector<std::string> face_names(int dimensions) {
  std::vector<std::string> names;
  for (const std::string& axis : axis_names(dimensions)) {
    names.push_back(axis + "-");
    names.push_back(axis + "+");
  }
  return names;
}

// The faces of a container wall left open; a solid wall has none, so `open` is an error there.
std::vector<geometry::Face> read_open_faces(Reader& item, int dimensions, bool solid) {
  if (solid && item.contains("open"))
    throw item.error("open", "a solid wall (solid: true) has no open faces; remove 'open'");
  std::vector<geometry::Face> faces;
  for (const std::string& face : item.choices("open", face_names(dimensions)))
    faces.push_back({axis_index(face), face.back() == '+' ? 1 : -1});
  return faces;
}

WallMaterial read_material(Reader& item) {
  Reader section = item.optional_map("material");
  WallMaterial material;
  material.youngs_modulus =
      section.optional<double>("youngs_modulus", material.youngs_modulus, kPositive);
  material.poisson_ratio =
      section.optional<double>("poisson_ratio", material.poisson_ratio, kNonNegative);
  if (!(material.poisson_ratio < 0.5))
    throw section.error("poisson_ratio", "must lie in [0, 0.5)");
  if (section.contains("restitution")) {
    material.restitution = section.required<double>("restitution", kPositive);
    if (*material.restitution > 1.0)
      throw section.error("restitution", "must lie in (0, 1]");
  }
  if (section.contains("friction"))
    material.friction = section.required<double>("friction", kNonNegative);
  if (section.contains("rolling_friction"))
    material.rolling_friction = section.required<double>("rolling_friction", kNonNegative);
  section.done();
  return material;
}

// A mesh wall: a closed mesh is a shape (SPH can lay particles in or around it) and a surface;
// an open one (a shell, a vessel without a lid) only a surface, for DEM.
void read_mesh_wall(Reader& item, WallSpec& wall, int dimensions,
                    const std::filesystem::path& folder) {
  MeshItem mesh = read_mesh_item(item, dimensions, folder);
  try {
    wall.shape = std::make_shared<geometry::TriangleMesh>(mesh.triangles, Vec3::Zero());
  } catch (const InputError& error) {
    wall.no_shape = item.error("file", fmt::format("the mesh {} is not a closed surface ({})",
                                                   mesh.file, error.message()));
    wall.surface = std::make_shared<geometry::MeshShellSurface>(mesh.triangles);
  }
}

WallSpec read_wall(Reader& item, int dimensions, const std::filesystem::path& folder) {
  WallSpec wall;
  const std::string kind = item.required_choice("shape", kShapes);
  if (has_fixed_side(kind)) {
    for (const std::string key : {"solid", "open"}) {
      if (item.contains(key))
        throw item.error(key, fmt::format("a {} wall has no '{}': its sides are fixed", kind, key));
    }
  }
  if (kind == "mesh")
    read_mesh_wall(item, wall, dimensions, folder);
  else
    wall.shape = read_shape_of(kind, item, dimensions, folder);
  wall.solid = has_fixed_side(kind) ? false : item.optional<bool>("solid", false);
  wall.open_faces = has_fixed_side(kind) ? std::vector<geometry::Face>{}
                                         : read_open_faces(item, dimensions, wall.solid);
  if (wall.shape)
    wall.surface = wall.shape->make_surface(wall.solid, wall.open_faces);
  wall.motion = read_motion(item, dimensions);
  wall.material = read_material(item);
  wall.boundary = item.choice("boundary", "no_slip", {"no_slip", "slip", "friction"});
  if (wall.boundary == "friction" && !wall.material.friction)
    throw item.error("boundary", "boundary: friction needs material.friction (mu_w)");
  return wall;
}

}  // namespace

std::vector<WallSpec> read_walls(Reader& root, int dimensions,
                                 const std::filesystem::path& case_folder) {
  std::vector<WallSpec> walls;
  for (Reader& item : root.optional_list("walls")) {
    walls.push_back(read_wall(item, dimensions, case_folder));
    item.done();
  }
  return walls;
}

}  // namespace partimix::io
