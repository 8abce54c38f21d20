#include "sph/implicit_viscosity.hpp"

#include <algorithm>
#include <cmath>

#include <omp.h>

#include "core/sparse_storage.hpp"
#include "sph/pair_rates.hpp"

namespace partimix::sph {

ImplicitViscosity::ImplicitViscosity(double tolerance, int max_iterations)
    : solver_(tolerance, max_iterations) {}

// Row i's partners: fluid ones and the diagonal sorted by index, then the walls (whose indices
// follow the fluid's).
void ImplicitViscosity::gather_row(std::size_t i, const Fields& f, const CellGrid& grid,
                                   const KernelTable& kernel, const KernelTable& gradient_kernel,
                                   const Parameters& p, std::vector<Partner>& out) {
  const double rho2 = p.reference_density * p.reference_density;
  const std::size_t first = out.size();
  out.push_back({static_cast<std::uint32_t>(i), 0.0, 0.0});
  grid.for_each_neighbour(i, f.position, [&](std::size_t j, const Vec3&, double r2) {
    if (j == i)
      return;
    const double r = std::sqrt(r2);
    const double factor = f.mass[j] * -(r * gradient_kernel.derivative(r)) / (rho2 * (r2 + p.eta2));
    const double weight = is_fluid(f.kind[j]) ? 0.0 : kernel.value(r);
    out.push_back({static_cast<std::uint32_t>(j), factor, weight});
  });
  std::sort(out.begin() + static_cast<std::ptrdiff_t>(first), out.end(),
            [](const Partner& a, const Partner& b) { return a.index < b.index; });
}

void ImplicitViscosity::gather_pairs(const Fields& f, std::size_t fluid_count, const CellGrid& grid,
                                     const KernelTable& kernel, const KernelTable& gradient_kernel,
                                     const Parameters& p) {
  const auto threads = static_cast<std::size_t>(omp_get_max_threads());
  thread_partners_.resize(threads);
  for (std::vector<Partner>& local : thread_partners_)
    local.clear();
  row_start_.assign(fluid_count + 1, 0);
  wall_start_.assign(fluid_count, 0);
#pragma omp parallel
  {
    const auto thread = static_cast<std::size_t>(omp_get_thread_num());
    std::vector<Partner>& local = thread_partners_[thread];
    // A static schedule gives each thread one block of rows, in thread order, so the threads'
    // lists joined in that order hold the rows in order.
#pragma omp for schedule(static)
    for (std::ptrdiff_t ii = 0; ii < static_cast<std::ptrdiff_t>(fluid_count); ++ii) {
      const auto i = static_cast<std::size_t>(ii);
      const std::size_t before = local.size();
      gather_row(i, f, grid, kernel, gradient_kernel, p, local);
      row_start_[i + 1] = local.size() - before;
      const auto walls =
          std::find_if(local.begin() + static_cast<std::ptrdiff_t>(before), local.end(),
                       [fluid_count](const Partner& q) { return q.index >= fluid_count; });
      wall_start_[i] = static_cast<std::size_t>(walls - local.begin()) - before;
    }
  }
  for (std::size_t i = 0; i < fluid_count; ++i) {
    row_start_[i + 1] += row_start_[i];
    wall_start_[i] += row_start_[i];
  }
  partners_.clear();
  for (const std::vector<Partner>& local : thread_partners_)
    partners_.insert(partners_.end(), local.begin(), local.end());
  lay_out_matrix(fluid_count);
}

// The matrix's rows and columns from the partners; the values come with each solve.
void ImplicitViscosity::lay_out_matrix(std::size_t fluid_count) {
  const auto n = static_cast<Eigen::Index>(fluid_count);
  matrix_.resize(n, n);
  std::size_t nonzeros = 0;
  for (std::size_t i = 0; i < fluid_count; ++i)
    nonzeros += wall_start_[i] - row_start_[i];
  resize_nonzeros_with_room(matrix_, static_cast<Eigen::Index>(nonzeros));
  std::size_t k = 0;
  for (std::size_t i = 0; i < fluid_count; ++i) {
    matrix_.outerIndexPtr()[i] = static_cast<int>(k);
    for (std::size_t q = row_start_[i]; q < wall_start_[i]; ++q)
      matrix_.innerIndexPtr()[k++] = static_cast<int>(partners_[q].index);
  }
  matrix_.outerIndexPtr()[fluid_count] = static_cast<int>(k);
}

// Row i: (1 + dt sum_j c_ij (1 + a_ij)) u*_i - dt sum_(j fluid) c_ij u*_j
//        = u^n_i + dt g + dt sum_(w wall) c_iw (u~_w + a_iw u^n_i),
// c_ij = factor_ij times the pair viscosity (eta_i + eta_j or its harmonic form; eta_w = eta_i).
// The ghost velocity u~_w, from the velocities of u^n, holds -a_iw u^n_i, a_iw = beta_w W_iw /
// sum_f W_wf (sph/wall_state.hpp): that share is taken at u*_i instead (a_ij = 0 for the fluid),
// so the ghost velocity's lag cannot feed a particle's own velocity back into itself
// (docs/sph.md, "Implicit viscosity").
void ImplicitViscosity::fill_row(std::size_t i, const Fields& f, const Parameters& p,
                                 const Vec3& start, const Vec3& acceleration, double dt) {
  const double eta_i = f.viscosity[i];
  double diagonal = 1.0;
  Vec3 rhs = start + dt * acceleration;
  double* values = matrix_.valuePtr() + matrix_.outerIndexPtr()[i];
  double* diagonal_value = values;
  for (std::size_t q = row_start_[i]; q < wall_start_[i]; ++q, ++values) {
    const Partner& j = partners_[q];
    if (j.index == i) {
      diagonal_value = values;
      continue;
    }
    const double c_ij = j.factor * pair_viscosity(eta_i, f.viscosity[j.index], p);
    diagonal += dt * c_ij;
    *values = -dt * c_ij;
  }
  const double eta_wall = pair_viscosity(eta_i, eta_i, p);
  for (std::size_t q = wall_start_[i]; q < row_start_[i + 1]; ++q) {
    const Partner& w = partners_[q];
    const double c_iw = w.factor * eta_wall;
    const double own_share = w.weight * f.ghost_weight[w.index];
    diagonal += dt * c_iw * (1.0 + own_share);
    rhs += (dt * c_iw) * (f.wall_velocity[w.index] + own_share * start);
  }
  *diagonal_value = diagonal;
  rhs_.row(static_cast<Eigen::Index>(i)) = rhs.transpose();
}

LinearSolve ImplicitViscosity::solve(Fields& f, std::size_t fluid_count, const Parameters& p,
                                     const std::vector<Vec3>& start,
                                     std::span<const Vec3> explicit_acceleration, double dt) {
  const auto n = static_cast<Eigen::Index>(fluid_count);
  rhs_.resize(n, 3);
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t ii = 0; ii < static_cast<std::ptrdiff_t>(fluid_count); ++ii) {
    const auto i = static_cast<std::size_t>(ii);
    const Vec3 acceleration =
        explicit_acceleration.empty() ? p.gravity : Vec3(p.gravity + explicit_acceleration[i]);
    fill_row(i, f, p, start[i], acceleration, dt);
  }
  solver_.compute(matrix_);
  LinearSolve result;
  component_.resize(n);
  for (int axis = 0; axis < p.dimensions; ++axis) {
    for (std::size_t i = 0; i < fluid_count; ++i)
      component_[static_cast<Eigen::Index>(i)] = f.velocity[i][axis];
    const LinearSolve solve = solver_.solve(matrix_, rhs_.col(axis), component_);
    result.iterations = std::max(result.iterations, solve.iterations);
    result.residual = std::max(result.residual, solve.residual);
    result.converged = result.converged && solve.converged;
    for (std::size_t i = 0; i < fluid_count; ++i)
      f.velocity[i][axis] = component_[static_cast<Eigen::Index>(i)];
  }
  return result;
}

}  // namespace partimix::sph
