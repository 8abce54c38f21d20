#pragma once
// Reading triangle meshes from STL files, ASCII and binary. An STL file is a soup: each triangle
// carries its own three corners and nothing says which triangles share them; the facet normals
// in the file are ignored because the corner order (counter-clockwise seen from outside) already
// gives the orientation and exporters often write zero or stale normals.
#include <array>
#include <string>
#include <vector>

#include "core/vec.hpp"

namespace partimix::geometry {

struct Triangle {
  std::array<Vec3, 3> corner;
};

using TriangleSoup = std::vector<Triangle>;

// The triangles of the STL file at `path`, every coordinate multiplied by `scale` (for example
// 1e-3 for a file drawn in millimetres). A file is binary when its size is exactly 84 + 50 n
// bytes for the count n in its header, even if the header starts with "solid" as many exporters
// write; otherwise it is read as ASCII if it holds no zero byte (which binary files always do).
// Throws InputError naming the file (and the line, for ASCII) on a missing or unreadable file, a
// truncated binary file, a malformed ASCII line, a non-finite coordinate or no triangle at all.
TriangleSoup read_stl(const std::string& path, double scale = 1.0);

}  // namespace partimix::geometry
