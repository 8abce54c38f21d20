#pragma once
// Axis names of case files: x, y (2D) and z (3D).
#include <string>
#include <vector>

namespace partimix::io {

inline std::vector<std::string> axis_names(int dimensions) {
  return dimensions == 2 ? std::vector<std::string>{"x", "y"}
                         : std::vector<std::string>{"x", "y", "z"};
}

inline int axis_index(const std::string& name) {
  return name.front() - 'x';
}

}  // namespace partimix::io
