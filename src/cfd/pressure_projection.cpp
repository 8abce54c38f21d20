#include "cfd/pressure_projection.hpp"

#include <algorithm>
#include <cmath>

#include "cfd/continuity_residual.hpp"
#include "cfd/face_stencil.hpp"

namespace partimix::cfd {
namespace {

constexpr std::int64_t kClosed = -1;
constexpr std::int64_t kHeld = -2;

}  // namespace

PressureProjection::PressureProjection(double tolerance, int max_iterations)
    : tolerance_(tolerance), solver_(tolerance, max_iterations) {}

// Regions of open cells joined through open faces, by breadth-first search; the first cell of
// each (in index order) is held at φ = 0 unless the region has an outlet face.
void PressureProjection::find_regions(const grid::StaggeredGrid& grid, const FlowMask& mask) {
  region_.assign(grid.cell_count(), -1);
  unknown_.assign(grid.cell_count(), kClosed);
  std::vector<std::size_t> queue;
  region_outlet_.clear();
  int regions = 0;
  for (std::size_t seed = 0; seed < grid.cell_count(); ++seed) {
    if (!mask.open_cell[seed] || region_[seed] >= 0)
      continue;
    region_[seed] = regions;
    queue.assign(1, seed);
    bool outlet = false;
    for (std::size_t q = 0; q < queue.size(); ++q) {
      const std::size_t c = queue[q];
      const Coordinates cell = grid.cell_coordinates(c);
      grid.for_each_face_of_cell(
          cell[0], cell[1], cell[2], [&](int axis, std::size_t face, int, std::int64_t n) {
            outlet = outlet || mask.outlet_face[axis][face];
            if (!mask.open_face[axis][face] || region_[static_cast<std::size_t>(n)] >= 0)
              return;
            region_[static_cast<std::size_t>(n)] = regions;
            queue.push_back(static_cast<std::size_t>(n));
          });
    }
    unknown_[seed] = outlet ? kClosed : kHeld;
    region_outlet_.push_back(outlet ? 1 : 0);
    ++regions;
  }
  region_sum_.assign(static_cast<std::size_t>(regions), 0.0);
  region_volume_.assign(static_cast<std::size_t>(regions), 0.0);
}

void PressureProjection::lay_out(const grid::StaggeredGrid& grid, const FlowMask& mask) {
  find_regions(grid, mask);
  row_cell_.clear();
  for (std::size_t c = 0; c < grid.cell_count(); ++c) {
    if (region_[c] < 0 || unknown_[c] == kHeld)
      continue;
    unknown_[c] = static_cast<std::int64_t>(row_cell_.size());
    row_cell_.push_back(c);
  }
  pattern_.clear();
  terms_.clear();
  grid.for_each_cell([&](const Coordinates& cell, std::size_t c) {
    if (unknown_[c] >= 0)
      lay_out_row(grid, mask, cell[0], cell[1], cell[2]);
  });
  pattern_.apply(matrix_);
  rhs_.setZero(matrix_.rows());
  solution_.setZero(matrix_.rows());
}

// The row of cell (i, j, k): a term per open face, which adds to the diagonal and, where the
// neighbour is an unknown, to its column (slot id 0 the diagonal, 1 + n the n-th term's
// neighbour).
void PressureProjection::lay_out_row(const grid::StaggeredGrid& grid, const FlowMask& mask, int i,
                                     int j, int k) {
  const std::size_t first = terms_.size();
  entries_.assign(1, {unknown_[grid.cell(i, j, k)], 0});
  grid.for_each_face_of_cell(i, j, k, [&](int axis, std::size_t face, int, std::int64_t n) {
    if (mask.outlet_face[axis][face]) {
      terms_.push_back({axis, face, 0, -1, true});
      return;
    }
    if (!mask.open_face[axis][face])
      return;
    const std::int64_t column = unknown_[static_cast<std::size_t>(n)];
    if (column >= 0)
      entries_.emplace_back(column, static_cast<int>(terms_.size() - first) + 1);
    terms_.push_back({axis, face, 0, -1, false});
  });
  slots_.assign(terms_.size() - first + 1, -1);
  pattern_.add_row(entries_, slots_);
  for (std::size_t t = first; t < terms_.size(); ++t) {
    terms_[t].diagonal = slots_[0];
    terms_[t].off_diagonal = slots_[t - first + 1];
  }
}

void PressureProjection::fill_matrix(const grid::StaggeredGrid& grid,
                                     const FaceArrays& void_fraction,
                                     const FaceArrays& coefficient) {
  double* values = matrix_.valuePtr();
  std::fill(values, values + matrix_.nonZeros(), 0.0);
  for (const FaceTerm& term : terms_) {
    const double w = (term.outlet ? 2.0 : 1.0) * void_fraction[term.axis][term.face] *
                     coefficient[term.axis][term.face] * grid.face_area(term.axis) /
                     grid.spacing(term.axis);
    values[term.diagonal] += w;
    if (term.off_diagonal >= 0)
      values[term.off_diagonal] -= w;
  }
}

// b_c = -(Σ ±ε_f u*_f A_f + V s_c) on every open cell, less its region's mean where the region
// has no outlet.
void PressureProjection::fill_rhs(const grid::StaggeredGrid& grid, const FaceArrays& void_fraction,
                                  const std::vector<double>& source, const FaceArrays& velocity) {
  std::fill(region_sum_.begin(), region_sum_.end(), 0.0);
  std::fill(region_volume_.begin(), region_volume_.end(), 0.0);
  cell_rhs_.assign(grid.cell_count(), 0.0);
  grid.for_each_cell([&](const std::array<int, 3>& cell, std::size_t c) {
    if (region_[c] < 0)
      return;
    const double outflow = cell_outflow(grid, cell[0], cell[1], cell[2], void_fraction, velocity);
    cell_rhs_[c] = -(outflow + grid.cell_volume() * source[c]);
    region_sum_[static_cast<std::size_t>(region_[c])] += cell_rhs_[c];
    region_volume_[static_cast<std::size_t>(region_[c])] += grid.cell_volume();
  });
  imbalance_ = 0.0;
  for (std::size_t r = 0; r < region_sum_.size(); ++r) {
    if (region_outlet_[r])
      region_sum_[r] = 0.0;
    imbalance_ = std::max(imbalance_, std::abs(region_sum_[r]) / region_volume_[r]);
  }
  for (std::size_t row = 0; row < row_cell_.size(); ++row) {
    const std::size_t c = row_cell_[row];
    const auto r = static_cast<std::size_t>(region_[c]);
    rhs_[static_cast<Eigen::Index>(row)] =
        cell_rhs_[c] - region_sum_[r] * grid.cell_volume() / region_volume_[r];
  }
}

void PressureProjection::correct(const grid::StaggeredGrid& grid, const FlowMask& mask,
                                 const FaceArrays& coefficient,
                                 const std::vector<double>& correction,
                                 FaceArrays& velocity) const {
  for (int axis = 0; axis < grid.dimensions(); ++axis)
    grid.for_each_face(axis, [&](const Coordinates& f, std::size_t index) {
      if (mask.outlet_face[axis][index]) {
        Coordinates cell = f;
        cell[axis] = f[axis] == 0 ? 0 : f[axis] - 1;
        const double phi = correction[cell_index(grid, cell)];
        const double gradient = (f[axis] == 0 ? phi : -phi) / (0.5 * grid.spacing(axis));
        velocity[axis][index] -= coefficient[axis][index] * gradient;
        return;
      }
      if (!mask.open_face[axis][index])
        return;
      velocity[axis][index] -=
          coefficient[axis][index] * gradient_across(grid, axis, f, correction);
    });
}

LinearSolve PressureProjection::solve_directly(const LinearSolve& iterative) {
  const Eigen::SparseMatrix<double> a = matrix_;
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> factors(a);
  if (factors.info() != Eigen::Success)
    return iterative;
  solution_ = factors.solve(rhs_);
  const double residual = (rhs_ - a * solution_).norm() / rhs_.norm();
  return {iterative.iterations, residual, residual <= tolerance_};
}

void PressureProjection::set_guess(const std::vector<double>& correction) {
  for (std::size_t row = 0; row < row_cell_.size(); ++row)
    solution_[static_cast<Eigen::Index>(row)] = correction[row_cell_[row]];
}

LinearSolve PressureProjection::project(const grid::StaggeredGrid& grid, const FlowMask& mask,
                                        const FaceArrays& void_fraction,
                                        const FaceArrays& coefficient,
                                        const std::vector<double>& source, FaceArrays& velocity,
                                        std::vector<double>& correction) {
  fill_matrix(grid, void_fraction, coefficient);
  fill_rhs(grid, void_fraction, source, velocity);
  LinearSolve result;
  if (!row_cell_.empty()) {
    multigrid_.compute(matrix_);
    result = solver_.solve(matrix_, multigrid_, rhs_, solution_);
    if (!result.converged)
      result = solve_directly(result);
  }
  correction.assign(grid.cell_count(), 0.0);
  for (std::size_t row = 0; row < row_cell_.size(); ++row)
    correction[row_cell_[row]] = solution_[static_cast<Eigen::Index>(row)];
  correct(grid, mask, coefficient, correction, velocity);
  return result;
}

}  // namespace partimix::cfd
