#include "cfd/cell_shear_rate.hpp"

#include <cmath>

#include "cfd/face_stencil.hpp"

namespace partimix::cfd {
namespace {

// Component a at the centre of cell c: the mean of its two faces along a.
double centre_value(const grid::StaggeredGrid& grid, const FaceArrays& velocity, int a,
                    const Coordinates& c) {
  Coordinates upper = c;
  upper[a] = grid.wrap_face(a, c[a] + 1);
  return 0.5 * (velocity[a][face_index(grid, a, c)] + velocity[a][face_index(grid, a, upper)]);
}

// ∂u_a/∂x_b at cell c (b ≠ a): the neighbours' centre values, or a wall's half a cell away.
double cross_gradient(const grid::StaggeredGrid& grid, const FlowMask& mask, const BoxSides& sides,
                      const WallFaces& walls, const FaceArrays& velocity, int a, int b,
                      const Coordinates& c) {
  const double h = grid.spacing(b);
  const double own = centre_value(grid, velocity, a, c);
  double value[2];
  double distance[2];
  for (int s = 0; s < 2; ++s) {
    const int side = s == 0 ? -1 : 1;
    Coordinates n = c;
    n[b] = grid.wrap_cell(b, c[b] + side);
    if (n[b] >= 0 && mask.open_cell[cell_index(grid, n)]) {
      value[s] = centre_value(grid, velocity, a, n);
      distance[s] = h;
      continue;
    }
    distance[s] = 0.5 * h;
    if (n[b] >= 0) {  // a blocked cell: its wall's velocity on the face between
      Coordinates face = c;
      face[b] = side < 0 ? c[b] : grid.wrap_face(b, c[b] + 1);
      value[s] = walls.at(b, face_index(grid, b, face))[a];
      continue;
    }
    const BoxSide& wall = box_side(sides, b, side);
    value[s] = wall.slip || wall.outlet ? own : wall.velocity[a];
  }
  return (value[1] - value[0]) / (distance[0] + distance[1]);
}

}  // namespace

void cell_shear_rates(const grid::StaggeredGrid& grid, const FlowMask& mask, const BoxSides& sides,
                      const WallFaces& walls, const FaceArrays& velocity,
                      std::vector<double>& out) {
  out.assign(grid.cell_count(), 0.0);
  const int dims = grid.dimensions();
  grid.for_each_cell([&](const Coordinates& c, std::size_t index) {
    if (!mask.open_cell[index])
      return;
    double g[3][3] = {};
    for (int a = 0; a < dims; ++a)
      for (int b = 0; b < dims; ++b) {
        if (a != b) {
          g[a][b] = cross_gradient(grid, mask, sides, walls, velocity, a, b, c);
          continue;
        }
        Coordinates upper = c;
        upper[a] = grid.wrap_face(a, c[a] + 1);
        g[a][a] = (velocity[a][face_index(grid, a, upper)] - velocity[a][face_index(grid, a, c)]) /
                  grid.spacing(a);
      }
    double sum = 0.0;
    for (int a = 0; a < dims; ++a)
      for (int b = 0; b < dims; ++b) {
        const double d = 0.5 * (g[a][b] + g[b][a]);
        sum += d * d;
      }
    out[index] = std::sqrt(2.0 * sum);
  });
}

}  // namespace partimix::cfd
