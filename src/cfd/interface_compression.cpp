#include "cfd/interface_compression.hpp"

#include <algorithm>
#include <cmath>

#include "cfd/face_stencil.hpp"

namespace partimix::cfd {
namespace {

// α of the open cell one step along `axis` from c, or c's own where that cell is closed or beyond
// the box (a one-sided difference there).
double neighbour_fraction(const grid::StaggeredGrid& grid, const FlowMask& mask,
                          const Coordinates& c, int axis, int side,
                          const std::vector<double>& fraction) {
  Coordinates n = c;
  n[axis] = grid.wrap_cell(axis, c[axis] + side);
  if (n[axis] < 0)
    return fraction[cell_index(grid, c)];
  const std::size_t index = cell_index(grid, n);
  return mask.open_cell[index] ? fraction[index] : fraction[cell_index(grid, c)];
}

}  // namespace

void InterfaceCompression::apply(const grid::StaggeredGrid& grid, const FlowMask& mask,
                                 const FaceArrays& void_fraction, const FaceArrays& velocity,
                                 const std::vector<double>& cells, double dt,
                                 std::vector<double>& fraction) {
  if (coefficient_ == 0.0)
    return;
  cell_gradients(grid, mask, fraction);
  face_rates(grid, mask, void_fraction, velocity, fraction);
  const double volume = grid.cell_volume();
  share_.assign(grid.cell_count(), 1.0);
  for (std::size_t c = 0; c < share_.size(); ++c)
    if (exchange_[c] > 0.0)
      share_[c] = std::min(1.0, kMostExchange * cells[c] * volume / (dt * exchange_[c]));
  change_.assign(grid.cell_count(), 0.0);
  for (int a = 0; a < grid.dimensions(); ++a)
    grid.for_each_face(a, [&](const Coordinates& f, std::size_t index) {
      const double rate = rate_[a][index];
      if (rate == 0.0)
        return;
      std::size_t below = 0;
      std::size_t above = 0;
      open_cell_beside(grid, mask, a, f, -1, below);
      open_cell_beside(grid, mask, a, f, 1, above);
      const std::size_t donor = rate > 0.0 ? below : above;
      const std::size_t acceptor = rate > 0.0 ? above : below;
      const double moved = std::min(share_[below], share_[above]) * dt * std::abs(rate) *
                           fraction[donor] * (1.0 - fraction[acceptor]);
      change_[donor] -= moved;
      change_[acceptor] += moved;
    });
  for (std::size_t c = 0; c < fraction.size(); ++c)
    if (mask.open_cell[c] && change_[c] != 0.0)
      fraction[c] += change_[c] / (cells[c] * volume);
}

// ∇α of each open cell by central differences, one-sided beside closed cells and the box's sides.
void InterfaceCompression::cell_gradients(const grid::StaggeredGrid& grid, const FlowMask& mask,
                                          const std::vector<double>& fraction) {
  gradients_.assign(3 * grid.cell_count(), 0.0);
  grid.for_each_cell([&](const Coordinates& c, std::size_t index) {
    if (!mask.open_cell[index])
      return;
    for (int a = 0; a < grid.dimensions(); ++a) {
      const double up = neighbour_fraction(grid, mask, c, a, 1, fraction);
      const double down = neighbour_fraction(grid, mask, c, a, -1, fraction);
      gradients_[3 * index + static_cast<std::size_t>(a)] = 0.5 * (up - down) / grid.spacing(a);
    }
  });
}

// c_α |ε_f u_f| A_f n_f on each face between two open cells, n_f the face's component of the unit
// normal ∇α / |∇α| (across the face from its two cells, along it their mean), with |∇α| kept
// above 1e-8 / h as OpenFOAM's interFoam does; and each cell's Σ |rate|.
void InterfaceCompression::face_rates(const grid::StaggeredGrid& grid, const FlowMask& mask,
                                      const FaceArrays& void_fraction, const FaceArrays& velocity,
                                      const std::vector<double>& fraction) {
  exchange_.assign(grid.cell_count(), 0.0);
  double smallest = grid.spacing(0);
  for (int a = 1; a < grid.dimensions(); ++a)
    smallest = std::min(smallest, grid.spacing(a));
  const double least_gradient = 1e-8 / smallest;
  for (int a = 0; a < grid.dimensions(); ++a) {
    rate_[a].assign(grid.face_count(a), 0.0);
    grid.for_each_face(a, [&](const Coordinates& f, std::size_t index) {
      std::size_t below = 0;
      std::size_t above = 0;
      if (!mask.open_face[a][index] || !open_cell_beside(grid, mask, a, f, -1, below) ||
          !open_cell_beside(grid, mask, a, f, 1, above) || fraction[below] == fraction[above])
        return;
      double squared = 0.0;
      double across = 0.0;
      for (int b = 0; b < grid.dimensions(); ++b) {
        const auto ub = static_cast<std::size_t>(b);
        const double g = b == a ? (fraction[above] - fraction[below]) / grid.spacing(a)
                                : 0.5 * (gradients_[3 * below + ub] + gradients_[3 * above + ub]);
        squared += g * g;
        if (b == a)
          across = g;
      }
      const double normal = across / (std::sqrt(squared) + least_gradient);
      const double rate = coefficient_ * std::abs(void_fraction[a][index] * velocity[a][index]) *
                          grid.face_area(a) * normal;
      rate_[a][index] = rate;
      exchange_[below] += std::abs(rate);
      exchange_[above] += std::abs(rate);
    });
  }
}

}  // namespace partimix::cfd
