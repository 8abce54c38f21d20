#include "cfd/phase_transport.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "cfd/face_stencil.hpp"

namespace partimix::cfd {
namespace {

// α_f between two open cells for a flux F along +axis: the upwind value plus the limited share
// of the jump to the downwind one; the upwind value where the cell beyond it is not open.
double face_fraction(const grid::StaggeredGrid& grid, const FlowMask& mask, int axis,
                     const Coordinates& f, double flux, const std::vector<double>& fraction) {
  const int upwind_side = flux > 0.0 ? -1 : 1;
  Coordinates upwind;
  Coordinates downwind;
  cell_beside(grid, axis, f, upwind_side, upwind);
  cell_beside(grid, axis, f, -upwind_side, downwind);
  const double a_u = fraction[cell_index(grid, upwind)];
  const double jump = fraction[cell_index(grid, downwind)] - a_u;
  Coordinates far = upwind;
  far[axis] = grid.wrap_cell(axis, upwind[axis] + upwind_side);
  if (jump == 0.0 || far[axis] < 0 || !mask.open_cell[cell_index(grid, far)])
    return a_u;
  const double r = (a_u - fraction[cell_index(grid, far)]) / jump;
  return a_u + 0.5 * superbee(r) * jump;
}

}  // namespace

double superbee(double r) {
  return std::max({0.0, std::min(2.0 * r, 1.0), std::min(r, 2.0)});
}

void PhaseTransport::advance(const grid::StaggeredGrid& grid, const FlowMask& mask,
                             const FaceArrays& void_fraction, const FaceArrays& velocity,
                             const std::vector<double>& old_cells,
                             const std::vector<double>& new_cells, double dt,
                             std::vector<double>& fraction) {
  change_.assign(grid.cell_count(), 0.0);
  for (int a = 0; a < grid.dimensions(); ++a)
    grid.for_each_face(a, [&](const Coordinates& f, std::size_t index) {
      const double flux = void_fraction[a][index] * velocity[a][index] * grid.face_area(a);
      if (flux == 0.0)
        return;
      std::size_t below = 0;
      std::size_t above = 0;
      const bool below_open = open_cell_beside(grid, mask, a, f, -1, below);
      const bool above_open = open_cell_beside(grid, mask, a, f, 1, above);
      double face = 0.0;
      if (mask.open_face[a][index]) {
        face = face_fraction(grid, mask, a, f, flux, fraction);
      } else if (below_open == above_open) {
        return;
      } else {
        const std::size_t inner = below_open ? below : above;
        const bool leaving = (flux > 0.0) == below_open;
        const bool box_side = f[a] == 0 || f[a] == grid.cells(a);
        if (leaving || !box_side)
          face = fraction[inner];
        else
          face = mask.outlet_face[a][index] ? 0.0 : 1.0;
      }
      if (below_open)
        change_[below] -= dt * flux * face;
      if (above_open)
        change_[above] += dt * flux * face;
    });
  const double volume = grid.cell_volume();
  for (std::size_t c = 0; c < fraction.size(); ++c)
    if (mask.open_cell[c])
      fraction[c] = (old_cells[c] * fraction[c] * volume + change_[c]) / (new_cells[c] * volume);
}

double PhaseTransport::stable_dt(const grid::StaggeredGrid& grid, const FlowMask& mask,
                                 const FaceArrays& void_fraction, const FaceArrays& velocity,
                                 const std::vector<double>& cells) const {
  outflow_.assign(grid.cell_count(), 0.0);
  for (int a = 0; a < grid.dimensions(); ++a)
    grid.for_each_face(a, [&](const Coordinates& f, std::size_t index) {
      const double flux = void_fraction[a][index] * velocity[a][index] * grid.face_area(a);
      std::size_t upwind = 0;
      if (flux != 0.0 && open_cell_beside(grid, mask, a, f, flux > 0.0 ? -1 : 1, upwind))
        outflow_[upwind] += std::abs(flux);
    });
  double dt = std::numeric_limits<double>::infinity();
  for (std::size_t c = 0; c < cells.size(); ++c)
    if (mask.open_cell[c] && outflow_[c] > 0.0)
      dt = std::min(dt, kMostOutflow * cells[c] * grid.cell_volume() / outflow_[c]);
  return dt;
}

}  // namespace partimix::cfd
