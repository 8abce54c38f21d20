#pragma once
// STL file contents for tests (the formats of docs/geometry-meshes.md): ASCII with full double
// precision, and binary with float32 coordinates and zero normals.
#include <bit>
#include <cstdint>
#include <sstream>
#include <string>

#include "geometry/stl_reader.hpp"

namespace partimix::test_support {

inline std::string ascii_stl(const geometry::TriangleSoup& triangles, const std::string& name) {
  std::ostringstream out;
  out.precision(17);
  out << "solid " << name << "\n";
  for (const geometry::Triangle& t : triangles) {
    out << "  facet normal 0 0 0\n    outer loop\n";
    for (const Vec3& c : t.corner) {
      out << "      vertex " << c.x() << " " << c.y() << " " << c.z() << "\n";
    }
    out << "    endloop\n  endfacet\n";
  }
  out << "endsolid " << name << "\n";
  return out.str();
}

inline void append_u32(std::string& bytes, std::uint32_t value) {
  for (int shift = 0; shift < 32; shift += 8) {
    bytes.push_back(static_cast<char>((value >> shift) & 0xFFu));
  }
}

inline void append_float(std::string& bytes, double value) {
  append_u32(bytes, std::bit_cast<std::uint32_t>(static_cast<float>(value)));
}

inline std::string binary_stl(const geometry::TriangleSoup& triangles, const std::string& header) {
  std::string bytes = header;
  bytes.resize(80, ' ');
  append_u32(bytes, static_cast<std::uint32_t>(triangles.size()));
  for (const geometry::Triangle& t : triangles) {
    for (int i = 0; i < 3; ++i) {
      append_float(bytes, 0.0);
    }
    for (const Vec3& c : t.corner) {
      for (int axis = 0; axis < 3; ++axis) {
        append_float(bytes, c[axis]);
      }
    }
    bytes.append(2, '\0');
  }
  return bytes;
}

}  // namespace partimix::test_support
