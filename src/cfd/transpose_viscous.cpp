#include "cfd/transpose_viscous.hpp"

#include <algorithm>

#include "cfd/face_stencil.hpp"

namespace partimix::cfd {
namespace {

struct Fields {
  const grid::StaggeredGrid& grid;
  const FlowMask& mask;
  const std::vector<double>& void_fraction;
  const std::vector<double>& viscosity;
  const FaceArrays& velocity;
};

double eps_eta(const Fields& s, const Coordinates& c) {
  const std::size_t index = cell_index(s.grid, c);
  return s.void_fraction[index] * s.viscosity[index];
}

// ε η ∂_a u_a at the centre of cell c.
double normal_stress(const Fields& s, int a, const Coordinates& c) {
  Coordinates upper = c;
  upper[a] = s.grid.wrap_face(a, c[a] + 1);
  const double gradient =
      (s.velocity[a][face_index(s.grid, a, upper)] - s.velocity[a][face_index(s.grid, a, c)]) /
      s.grid.spacing(a);
  return eps_eta(s, c) * gradient;
}

// ε η ∂_a u_b on the edge between cells `below` and `above` (along a) at the faces of component b
// numbered `level` along b.
double edge_stress(const Fields& s, int a, int b, const Coordinates& below,
                   const Coordinates& above, int level) {
  Coordinates fb_below = below;
  Coordinates fb_above = above;
  fb_below[b] = fb_above[b] = level;
  const double gradient = (s.velocity[b][face_index(s.grid, b, fb_above)] -
                           s.velocity[b][face_index(s.grid, b, fb_below)]) /
                          s.grid.spacing(a);
  double sum = 0.0;
  int count = 0;
  for (const Coordinates& c : {below, above})
    for (const int shift : {-1, 0}) {
      Coordinates cell = c;
      cell[b] = s.grid.wrap_cell(b, level + shift);
      if (cell[b] < 0 || !s.mask.open_cell[cell_index(s.grid, cell)])
        continue;
      sum += eps_eta(s, cell);
      ++count;
    }
  return count > 0 ? sum / count * gradient : 0.0;
}

double face_term(const Fields& s, int a, const Coordinates& f) {
  Coordinates below;
  Coordinates above;
  cell_beside(s.grid, a, f, -1, below);
  cell_beside(s.grid, a, f, 1, above);
  double term = (normal_stress(s, a, above) - normal_stress(s, a, below)) / s.grid.spacing(a);
  for (int b = 0; b < s.grid.dimensions(); ++b) {
    if (b == a)
      continue;
    const int lower = f[b];
    const int upper = s.grid.wrap_face(b, f[b] + 1);
    term +=
        (edge_stress(s, a, b, below, above, upper) - edge_stress(s, a, b, below, above, lower)) /
        s.grid.spacing(b);
  }
  return term;
}

}  // namespace

void transpose_viscous_term(const grid::StaggeredGrid& grid, const FlowMask& mask,
                            const std::vector<double>& void_fraction,
                            const std::vector<double>& viscosity, const FaceArrays& velocity,
                            FaceArrays& out) {
  const Fields s{grid, mask, void_fraction, viscosity, velocity};
  for (int a = 0; a < grid.dimensions(); ++a) {
    std::fill(out[a].begin(), out[a].end(), 0.0);
    grid.for_each_face(a, [&](const Coordinates& f, std::size_t index) {
      if (mask.open_face[a][index])
        out[a][index] = face_term(s, a, f);
    });
  }
}

}  // namespace partimix::cfd
