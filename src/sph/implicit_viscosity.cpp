#include "sph/implicit_viscosity.hpp"

#include <algorithm>
#include <cmath>

#include "sph/pair_rates.hpp"

namespace partimix::sph {

ImplicitViscosity::ImplicitViscosity(double tolerance, int max_iterations) {
  solver_.setTolerance(tolerance);
  solver_.setMaxIterations(max_iterations);
}

// Row i: (1 + dt sum_j c_ij) u*_i - dt sum_(j fluid) c_ij u*_j
//        = u^n_i + dt g + dt sum_(w wall) c_iw u~_w.
void ImplicitViscosity::add_row(std::size_t i, const Fields& f, std::size_t fluid_count,
                                const CellGrid& grid, const KernelTable& kernel,
                                const Parameters& p, const Vec3& start, double dt) {
  const double rho2 = p.reference_density * p.reference_density;
  const double eta_i = f.viscosity[i];
  double diagonal = 1.0;
  Vec3 rhs = start + dt * p.gravity;
  grid.for_each_neighbour(i, f.position, [&](std::size_t j, const Vec3&, double r2) {
    if (j == i)
      return;
    const double r = std::sqrt(r2);
    const double r_dot_grad = r * kernel.derivative(r);
    const bool fluid_j = j < fluid_count;
    const double eta_j = fluid_j ? f.viscosity[j] : eta_i;
    const double eta_sum = pair_viscosity(eta_i, eta_j, p);
    const double c_ij = f.mass[j] * eta_sum * -r_dot_grad / (rho2 * (r2 + p.eta2));
    diagonal += dt * c_ij;
    if (fluid_j)
      entries_.emplace_back(static_cast<int>(i), static_cast<int>(j), -dt * c_ij);
    else
      rhs += (dt * c_ij) * f.wall_velocity[j];
  });
  entries_.emplace_back(static_cast<int>(i), static_cast<int>(i), diagonal);
  rhs_.row(static_cast<Eigen::Index>(i)) = rhs.transpose();
}

LinearSolve ImplicitViscosity::solve(Fields& f, std::size_t fluid_count, const CellGrid& grid,
                                     const KernelTable& gradient_kernel, const Parameters& p,
                                     const std::vector<Vec3>& start, double dt) {
  const auto n = static_cast<Eigen::Index>(fluid_count);
  entries_.clear();
  rhs_.resize(n, 3);
  for (std::size_t i = 0; i < fluid_count; ++i)
    add_row(i, f, fluid_count, grid, gradient_kernel, p, start[i], dt);
  matrix_.resize(n, n);
  matrix_.setFromTriplets(entries_.begin(), entries_.end());
  solver_.compute(matrix_);
  LinearSolve result;
  component_.resize(n);
  for (int axis = 0; axis < p.dimensions; ++axis) {
    for (std::size_t i = 0; i < fluid_count; ++i)
      component_[static_cast<Eigen::Index>(i)] = f.velocity[i][axis];
    component_ = solver_.solveWithGuess(rhs_.col(axis), component_);
    result.iterations = std::max(result.iterations, static_cast<int>(solver_.iterations()));
    result.residual = std::max(result.residual, solver_.error());
    result.converged = result.converged && solver_.info() == Eigen::Success;
    for (std::size_t i = 0; i < fluid_count; ++i)
      f.velocity[i][axis] = component_[static_cast<Eigen::Index>(i)];
  }
  return result;
}

}  // namespace partimix::sph
