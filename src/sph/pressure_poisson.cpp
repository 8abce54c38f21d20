#include "sph/pressure_poisson.hpp"

#include "sph/particle_shifting.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include <omp.h>
#include <vector>

#include "core/sparse_storage.hpp"

namespace partimix::sph {

namespace {

// u*_i - u_j; against a wall, less the velocity dt (g - a_w) that gravity and the wall's own
// acceleration gave the fluid in this step: the wall's extrapolated pressure (its row) already
// carries that part (docs/sph.md, "Incompressible SPH"), as it does in the weakly-compressible
// solver, whose continuity equation sees only the fluid's actual motion against the wall.
Vec3 relative_velocity(std::size_t i, std::size_t j, const Fields& f, const Parameters& p,
                       double dt) {
  const Vec3 relative = f.velocity[i] - f.velocity[j];
  if (is_fluid(f.kind[j]))
    return relative;
  Vec3 relative_gravity = p.gravity;
  if (f.body_acceleration != nullptr)
    relative_gravity -= (*f.body_acceleration)[j];
  return relative - dt * relative_gravity;
}

}  // namespace

PressurePoisson::PressurePoisson(double tolerance, int max_iterations)
    : solver_(tolerance, max_iterations) {}

// Row i: (sum_j A_ij) p_i - sum_j A_ij p_j = -rho0 (div u*)_i / dt with
// A_ij = -2 V_j (r_ij . grad_i W_ij) / (r_ij^2 + eta^2) >= 0, or p_i = 0 at a free surface.
bool PressurePoisson::add_fluid_row(std::size_t i, const Fields& f, const CellGrid& grid,
                                    const KernelTable& kernel, const Parameters& p, double dt,
                                    ThreadRows& rows) {
  const std::size_t first = rows.entries.size();
  double diagonal = 0.0;
  double divergence = 0.0;
  double position_divergence = 0.0;
  grid.for_each_neighbour(i, f.position, [&](std::size_t j, const Vec3& r_ij, double r2) {
    if (j == i)
      return;
    const double r = std::sqrt(r2);
    const Vec3 grad = (kernel.derivative(r) / r) * r_ij;
    const double volume = f.mass[j] / p.reference_density;
    const double r_dot_grad = r_ij.dot(grad);
    const double a_ij = -2.0 * volume * r_dot_grad / (r2 + p.eta2);
    rows.entries.emplace_back(static_cast<int>(j), -a_ij);
    diagonal += a_ij;
    divergence -= volume * relative_velocity(i, j, f, p, dt).dot(grad);
    position_divergence -= volume * r_dot_grad;
  });
  const auto row = static_cast<int>(i);
  if (at_free_surface(position_divergence, p.dimensions)) {
    rows.entries.resize(first);
    rows.entries.emplace_back(row, 1.0);
    rhs_[row] = 0.0;
    rows.close_row(row, first);
    return true;
  }
  rows.entries.emplace_back(row, diagonal);
  rhs_[row] = -p.reference_density * divergence / dt;
  rows.close_row(row, first);
  return false;
}

// Row w: p_w - sum_f (W_wf / sum W) p_f = rho0 (g - a_w) . sum_f r_wf W_wf / sum W, or p_w = 0
// without fluid around (Adami et al. 2012, eq. 27 with rho_f = rho0).
void PressurePoisson::add_wall_row(std::size_t w, const Fields& f, std::size_t fluid_count,
                                   const CellGrid& grid, const KernelTable& kernel,
                                   const Parameters& p, ThreadRows& rows) {
  const std::size_t first = rows.entries.size();
  double weight = 0.0;
  Vec3 moment = Vec3::Zero();
  grid.for_each_neighbour(
      w, f.position,
      [&](std::size_t j, const Vec3& r_wj, double r2) {
        const double W = kernel.value(std::sqrt(r2));
        weight += W;
        moment += W * r_wj;
        rows.entries.emplace_back(static_cast<int>(j), -W);
      },
      fluid_count);
  const auto row = static_cast<int>(w);
  if (weight <= 0.0) {
    rows.entries.resize(first);
    rows.entries.emplace_back(row, 1.0);
    rhs_[row] = 0.0;
    rows.close_row(row, first);
    return;
  }
  for (std::size_t k = first; k < rows.entries.size(); ++k)
    rows.entries[k].second /= weight;
  rows.entries.emplace_back(row, 1.0);
  Vec3 relative_gravity = p.gravity;
  if (f.body_acceleration != nullptr)
    relative_gravity -= (*f.body_acceleration)[w];
  rhs_[row] = p.reference_density * relative_gravity.dot(moment) / weight;
  rows.close_row(row, first);
}

// A finished row's entries sorted by column, as a compressed sparse row must hold them, those of
// one column (two periodic images of a particle in a short periodic domain) summed.
void PressurePoisson::ThreadRows::close_row(int row, std::size_t first) {
  const auto begin = entries.begin() + static_cast<std::ptrdiff_t>(first);
  std::sort(begin, entries.end());
  auto kept = begin;  // every row has its diagonal entry
  for (auto it = begin + 1; it != entries.end(); ++it) {
    if (it->first == kept->first)
      kept->second += it->second;
    else
      *++kept = *it;
  }
  entries.erase(kept + 1, entries.end());
  starts.emplace_back(row, first);
}

// Rows in parallel, each thread into its own buffers; then the compressed rows are laid out
// from the rows' lengths and filled in parallel, without a list of triplets to sort.
void PressurePoisson::assemble(const Fields& f, std::size_t fluid_count, const CellGrid& grid,
                               const KernelTable& kernel, const KernelTable& gradient_kernel,
                               const Parameters& p, double dt) {
  const std::size_t n = f.position.size();
  thread_rows_.resize(static_cast<std::size_t>(omp_get_max_threads()));
  for (ThreadRows& local : thread_rows_) {
    local.entries.clear();
    local.starts.clear();
  }
  bool dirichlet = false;
#pragma omp parallel reduction(|| : dirichlet)
  {
    ThreadRows& local = thread_rows_[static_cast<std::size_t>(omp_get_thread_num())];
#pragma omp for schedule(dynamic, 256)
    for (std::ptrdiff_t ii = 0; ii < static_cast<std::ptrdiff_t>(n); ++ii) {
      const auto i = static_cast<std::size_t>(ii);
      if (i < fluid_count)
        dirichlet = add_fluid_row(i, f, grid, gradient_kernel, p, dt, local) || dirichlet;
      else
        add_wall_row(i, f, fluid_count, grid, kernel, p, local);
    }
  }
  has_dirichlet_row_ = dirichlet;
  lay_out_matrix(n, fluid_count);
}

// Row lengths, their prefix sums as the outer index, then each thread copies its rows; without
// a free surface each fluid row's diagonal grows by the fraction kRegularisation, a uniform
// slight compressibility that takes up the incompatibility of the discrete source with the
// walls' rows evenly (a constant pressure, taken off after the solve) instead of at one pinned
// particle (docs/sph.md, "Incompressible SPH").
void PressurePoisson::lay_out_matrix(std::size_t n, std::size_t fluid_count) {
  matrix_.resize(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
  int* outer = matrix_.outerIndexPtr();
  outer[0] = 0;
  for (const ThreadRows& local : thread_rows_) {
    for (std::size_t k = 0; k < local.starts.size(); ++k) {
      const std::size_t end =
          k + 1 < local.starts.size() ? local.starts[k + 1].second : local.entries.size();
      outer[local.starts[k].first + 1] = static_cast<int>(end - local.starts[k].second);
    }
  }
  for (std::size_t i = 0; i < n; ++i)
    outer[i + 1] += outer[i];
  resize_nonzeros_with_room(matrix_, outer[n]);
  const double regularisation = has_dirichlet_row_ ? 1.0 : 1.0 + kRegularisation;
  const auto lists = static_cast<std::ptrdiff_t>(thread_rows_.size());
#pragma omp parallel for schedule(static, 1)
  for (std::ptrdiff_t t = 0; t < lists; ++t) {
    const ThreadRows& local = thread_rows_[static_cast<std::size_t>(t)];
    for (std::size_t k = 0; k < local.starts.size(); ++k) {
      const int row = local.starts[k].first;
      const std::size_t end =
          k + 1 < local.starts.size() ? local.starts[k + 1].second : local.entries.size();
      int slot = outer[row];
      for (std::size_t e = local.starts[k].second; e < end; ++e, ++slot) {
        const auto [column, value] = local.entries[e];
        matrix_.innerIndexPtr()[slot] = column;
        const bool scaled = column == row && static_cast<std::size_t>(row) < fluid_count;
        matrix_.valuePtr()[slot] = scaled ? value * regularisation : value;
      }
    }
  }
}

LinearSolve PressurePoisson::solve(Fields& f, std::size_t fluid_count, const CellGrid& grid,
                                   const KernelTable& kernel, const KernelTable& gradient_kernel,
                                   const Parameters& p, double dt) {
  const std::size_t n = f.position.size();
  rhs_.resize(static_cast<Eigen::Index>(n));
  assemble(f, fluid_count, grid, kernel, gradient_kernel, p, dt);
  multigrid_.compute(matrix_);
  if (solution_.size() != rhs_.size())
    solution_.setZero(rhs_.size());
  const double guess_offset = has_dirichlet_row_ ? 0.0 : mean_offset_;
  for (std::size_t i = 0; i < n; ++i)
    solution_[static_cast<Eigen::Index>(i)] = f.pressure[i] + guess_offset;
  const LinearSolve result = solver_.solve(matrix_, multigrid_, rhs_, solution_);
  double mean = 0.0;
  if (!has_dirichlet_row_) {
    for (std::size_t i = 0; i < fluid_count; ++i)
      mean += solution_[static_cast<Eigen::Index>(i)];
    mean /= static_cast<double>(fluid_count);
    mean_offset_ = mean;
  }
  for (std::size_t i = 0; i < n; ++i) {
    f.pressure[i] = solution_[static_cast<Eigen::Index>(i)] - mean;
    f.density[i] = p.reference_density;
  }
  return result;
}

void project_velocities(Fields& f, std::size_t fluid_count, const CellGrid& grid,
                        const KernelTable& kernel, const Parameters& p, double dt) {
  const double rho2 = p.reference_density * p.reference_density;
  const auto n = static_cast<std::ptrdiff_t>(fluid_count);
#pragma omp parallel for schedule(dynamic, 512)
  for (std::ptrdiff_t ii = 0; ii < n; ++ii) {
    const auto i = static_cast<std::size_t>(ii);
    Vec3 gradient = Vec3::Zero();  // grad p_i / rho0
    grid.for_each_neighbour(i, f.position, [&](std::size_t j, const Vec3& r_ij, double r2) {
      if (j == i)
        return;
      const double r = std::sqrt(r2);
      gradient +=
          (f.mass[j] * (f.pressure[i] + f.pressure[j]) / rho2 * kernel.derivative(r) / r) * r_ij;
    });
    f.velocity[i] -= dt * gradient;
  }
}

}  // namespace partimix::sph
