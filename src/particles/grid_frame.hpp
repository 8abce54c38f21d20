#pragma once
// The frame of a method on a grid (Solver::grid_frame): its cells' fields, written as VTK
// ImageData (io/vti_frame_writer.hpp) in place of its particles. The cells are the box
// [origin, origin + cells * spacing) turned by `direction` about the origin (a grid in a rotating
// frame), numbered x fastest; each array holds `components` doubles
// per cell, cell after cell. In 2D cells[2] is 1 and the image is flat (z extent 0).
#include <array>
#include <vector>

#include "core/vec.hpp"
#include "particles/frame_array.hpp"

namespace partimix {

struct GridFrame {
  int dimensions = 3;
  Vec3 origin = Vec3::Zero();
  Vec3 spacing = Vec3::Ones();
  std::array<int, 3> cells{1, 1, 1};
  std::vector<FrameArray> cell_arrays;
  Mat3 direction = Mat3::Identity();  // the grid's axes in the world, as columns

  std::size_t cell_count() const {
    return static_cast<std::size_t>(cells[0]) * static_cast<std::size_t>(cells[1]) *
           static_cast<std::size_t>(cells[2]);
  }
};

}  // namespace partimix
