#include "cfd/continuity_residual.hpp"

#include <algorithm>
#include <cmath>

namespace partimix::cfd {

double cell_outflow(const grid::StaggeredGrid& grid, int i, int j, int k,
                    const FaceArrays& void_fraction, const FaceArrays& velocity) {
  double outflow = 0.0;
  grid.for_each_face_of_cell(i, j, k, [&](int axis, std::size_t face, int side, auto) {
    outflow += side * void_fraction[axis][face] * velocity[axis][face] * grid.face_area(axis);
  });
  return outflow;
}

double continuity_residual(const grid::StaggeredGrid& grid, const FlowMask& mask,
                           const FaceArrays& void_fraction, const FaceArrays& velocity,
                           const std::vector<double>& source) {
  double largest = 0.0;
  grid.for_each_cell([&](const std::array<int, 3>& c, std::size_t index) {
    if (!mask.open_cell[index])
      return;
    const double outflow = cell_outflow(grid, c[0], c[1], c[2], void_fraction, velocity);
    largest = std::max(largest, std::abs(outflow / grid.cell_volume() + source[index]));
  });
  return largest;
}

}  // namespace partimix::cfd
