#pragma once
// The shapes of a case file (docs/case-reference.md, "Shapes"): the items of the regions
// (`fluid.regions`, `dem.fill.region`: box, cylinder, plate, mesh, truck_drum: its cavity) and of
// `walls` (those and plane, drum, cone), chosen by `shape`, each read with its own keys.
#include <filesystem>
#include <memory>
#include <string>

#include "core/vec.hpp"
#include "geometry/shape.hpp"
#include "geometry/stl_reader.hpp"
#include "io/yaml_reader.hpp"

namespace partimix::io {

// The shape described by `item`. A mesh file is found relative to `case_folder`, the folder
// of the case file, unless its path is absolute; any problem with the mesh is an InputError
// about the item's `file` key that quotes the mesh's own error.
std::shared_ptr<const geometry::Shape> read_shape(Reader& item, int dimensions,
                                                  const std::filesystem::path& case_folder);

// The shape named `shape` (box, cylinder, plate, mesh, or the wall shapes plane, drum, cone)
// from the keys of `item`, whose `shape` key the caller has read.
std::shared_ptr<const geometry::Shape> read_shape_of(const std::string& shape, Reader& item,
                                                     int dimensions,
                                                     const std::filesystem::path& case_folder);

// The keys of a mesh item: the triangles of its STL `file` (relative to `case_folder`) times
// `scale`, and `offset`, which the caller adds. A problem with the file is an InputError about
// `file` that quotes the file's own error.
struct MeshItem {
  std::string file;
  geometry::TriangleSoup triangles;  // scaled and moved by `offset`, checked (triangle_check.hpp)
};
MeshItem read_mesh_item(Reader& item, int dimensions, const std::filesystem::path& case_folder);

// Checks that `hi` exceeds `lo` on each of the first `dimensions` axes (a box, the domain); the
// error is about the key `max`.
void check_increasing(const Reader& reader, const Vec3& lo, const Vec3& hi, int dimensions);

}  // namespace partimix::io
