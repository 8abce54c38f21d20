#pragma once
// The `walls` list of a case file (docs/case-reference.md, "walls"): one geometry section for
// every method. Each wall is a shape (box, cylinder, plate, mesh, plane, drum, cone) with its
// open faces or `solid`, its motion and its material.
#include <filesystem>
#include <vector>

#include "io/case.hpp"
#include "io/yaml_reader.hpp"

namespace partimix::io {

std::vector<WallSpec> read_walls(Reader& root, int dimensions,
                                 const std::filesystem::path& case_folder);

}  // namespace partimix::io
