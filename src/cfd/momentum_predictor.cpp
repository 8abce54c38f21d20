#include "cfd/momentum_predictor.hpp"

#include <algorithm>

namespace partimix::cfd {

MomentumPredictor::MomentumPredictor(double tolerance, int max_iterations)
    : solvers_{ConjugateGradient(tolerance, max_iterations),
               ConjugateGradient(tolerance, max_iterations),
               ConjugateGradient(tolerance, max_iterations)} {}

void MomentumPredictor::lay_out(const grid::StaggeredGrid& grid, const FlowMask& mask) {
  for (int axis = 0; axis < grid.dimensions(); ++axis)
    lay_out_component(grid, mask, axis);
}

void MomentumPredictor::lay_out_component(const grid::StaggeredGrid& grid, const FlowMask& mask,
                                          int axis) {
  Component& component = components_[static_cast<std::size_t>(axis)];
  component.unknown.assign(grid.face_count(axis), -1);
  component.row_face.clear();
  for (std::size_t f = 0; f < grid.face_count(axis); ++f) {
    if (!mask.open_face[axis][f])
      continue;
    component.unknown[f] = static_cast<std::int64_t>(component.row_face.size());
    component.row_face.push_back(f);
  }
  pattern_.clear();
  component.terms.clear();
  component.term_start.assign(1, 0);
  grid.for_each_face(axis, [&](const Coordinates& f, std::size_t index) {
    if (mask.open_face[axis][index])
      lay_out_row(grid, mask, axis, f, component);
  });
  pattern_.apply(component.matrix);
  component.rhs.setZero(component.matrix.rows());
  component.solution.setZero(component.matrix.rows());
}

// Slot id 0 is the row's diagonal, 1 + n the n-th term's neighbour.
void MomentumPredictor::lay_out_row(const grid::StaggeredGrid& grid, const FlowMask& mask, int axis,
                                    const Coordinates& f, Component& component) {
  const std::size_t first = component.terms.size();
  const auto row = static_cast<std::uint32_t>(component.term_start.size() - 1);
  entries_.assign(1, {row, 0});
  for (int along = 0; along < grid.dimensions(); ++along)
    for (const int side : {-1, 1}) {
      Term term = link_to(grid, mask, axis, f, along, side, component);
      term.row = row;
      if (term.link == Link::unknown)
        entries_.emplace_back(component.unknown[term.neighbour],
                              static_cast<int>(component.terms.size() - first) + 1);
      component.terms.push_back(term);
    }
  slots_.assign(component.terms.size() - first + 1, -1);
  pattern_.add_row(entries_, slots_);
  for (std::size_t t = first; t < component.terms.size(); ++t) {
    component.terms[t].diagonal = slots_[0];
    component.terms[t].off_diagonal = slots_[t - first + 1];
  }
  component.term_start.push_back(component.terms.size());
}

// How the neighbour of open face f one step along `along` enters f's row, and the cells whose
// ε η make the coefficient.
MomentumPredictor::Term MomentumPredictor::link_to(const grid::StaggeredGrid& grid,
                                                   const FlowMask& mask, int axis,
                                                   const Coordinates& f, int along, int side,
                                                   const Component& component) const {
  Term term{
      0, Link::known,     static_cast<std::int8_t>(along), static_cast<std::int8_t>(side), 0, -1,
      0, {-1, -1, -1, -1}};
  auto open_cell = [&](Coordinates c) -> std::int64_t {
    if (c[along] < 0)
      return -1;
    const std::size_t index = cell_index(grid, c);
    return mask.open_cell[index] ? static_cast<std::int64_t>(index) : -1;
  };
  Coordinates below;
  Coordinates above;
  cell_beside(grid, axis, f, -1, below);
  cell_beside(grid, axis, f, 1, above);
  Coordinates neighbour;
  if (along == axis) {
    term.cells[0] = static_cast<std::int64_t>(cell_index(grid, side < 0 ? below : above));
    neighbour_face(grid, axis, f, axis, side, neighbour);
  } else {
    Coordinates below_next = below;
    Coordinates above_next = above;
    below_next[along] = above_next[along] = grid.wrap_cell(along, f[along] + side);
    term.cells = {open_cell(below), open_cell(above), open_cell(below_next), open_cell(above_next)};
    if (!neighbour_face(grid, axis, f, along, side, neighbour)) {
      term.link = Link::box_wall;
      return term;
    }
    if (term.cells[2] < 0 && term.cells[3] < 0) {
      term.link = Link::blocked_wall;
      term.wall_cell = static_cast<std::int64_t>(cell_index(grid, below_next));
      return term;
    }
  }
  term.neighbour = face_index(grid, axis, neighbour);
  term.link = component.unknown[term.neighbour] >= 0 ? Link::unknown : Link::known;
  return term;
}

void MomentumPredictor::fill(const grid::StaggeredGrid& grid, const BoxSides& sides, int axis,
                             const std::vector<double>& void_fraction,
                             const std::vector<double>& viscosity, const FaceArrays& diagonal,
                             const FaceArrays& rhs, const FaceArrays& velocity,
                             Component& component) const {
  double* values = component.matrix.valuePtr();
  std::fill(values, values + component.matrix.nonZeros(), 0.0);
  for (std::size_t row = 0; row < component.row_face.size(); ++row) {
    const std::size_t f = component.row_face[row];
    values[component.terms[component.term_start[row]].diagonal] = diagonal[axis][f];
    component.rhs[static_cast<Eigen::Index>(row)] = rhs[axis][f];
    component.solution[static_cast<Eigen::Index>(row)] = velocity[axis][f];
  }
  for (const Term& term : component.terms) {
    double sum = 0.0;
    int count = 0;
    for (const std::int64_t c : term.cells)
      if (c >= 0) {
        sum += void_fraction[static_cast<std::size_t>(c)] * viscosity[static_cast<std::size_t>(c)];
        ++count;
      }
    const double h = grid.spacing(term.along);
    const double coefficient = count > 0 ? sum / count / (h * h) : 0.0;
    double& b = component.rhs[term.row];
    switch (term.link) {
      case Link::unknown:
        values[term.diagonal] += coefficient;
        values[term.off_diagonal] -= coefficient;
        break;
      case Link::known:
        values[term.diagonal] += coefficient;
        b += coefficient * velocity[axis][term.neighbour];
        break;
      case Link::box_wall: {
        const BoxSide& wall = box_side(sides, term.along, term.side);
        if (wall.slip || wall.outlet)  // no stress across it
          break;
        values[term.diagonal] += 2.0 * coefficient;
        b += 2.0 * coefficient * wall.velocity[axis];
        break;
      }
      case Link::blocked_wall:
        values[term.diagonal] += 2.0 * coefficient;
        b += 2.0 * coefficient * term.wall_velocity;
        break;
    }
  }
}

void MomentumPredictor::set_wall_velocities(
    const grid::StaggeredGrid& grid,
    const std::function<Vec3(const Vec3&, std::size_t)>& velocity_at) {
  for (int axis = 0; axis < grid.dimensions(); ++axis) {
    Component& component = components_[static_cast<std::size_t>(axis)];
    for (Term& term : component.terms) {
      if (term.link != Link::blocked_wall)
        continue;
      const auto f = grid.face_coordinates(axis, component.row_face[term.row]);
      Vec3 x = grid.face_centre(axis, f[0], f[1], f[2]);
      x[term.along] += 0.5 * term.side * grid.spacing(term.along);
      term.wall_velocity = velocity_at(x, static_cast<std::size_t>(term.wall_cell))[axis];
    }
  }
}

LinearSolve MomentumPredictor::solve(const grid::StaggeredGrid& grid, const BoxSides& sides,
                                     const std::vector<double>& void_fraction,
                                     const std::vector<double>& viscosity,
                                     const FaceArrays& diagonal, const FaceArrays& rhs,
                                     FaceArrays& velocity) {
  LinearSolve all;
  for (int axis = 0; axis < grid.dimensions(); ++axis) {
    Component& component = components_[static_cast<std::size_t>(axis)];
    if (component.row_face.empty())
      continue;
    fill(grid, sides, axis, void_fraction, viscosity, diagonal, rhs, velocity, component);
    ConjugateGradient& solver = solvers_[static_cast<std::size_t>(axis)];
    solver.compute(component.matrix);
    const LinearSolve result = solver.solve(component.matrix, component.rhs, component.solution);
    all.iterations = std::max(all.iterations, result.iterations);
    all.residual = std::max(all.residual, result.residual);
    all.converged = all.converged && result.converged;
    for (std::size_t row = 0; row < component.row_face.size(); ++row)
      velocity[axis][component.row_face[row]] = component.solution[static_cast<Eigen::Index>(row)];
  }
  return all;
}

}  // namespace partimix::cfd
