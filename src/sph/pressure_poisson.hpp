#pragma once
// The pressure Poisson equation of the incompressible (projection) scheme, docs/sph.md
// "Incompressible SPH": one row per particle (fluid: the Laplacian of p / rho0 equals the
// divergence of the predicted velocity over dt; fluid at a free surface: p = 0; wall: Adami's
// extrapolation from the fluid), solved by BiCGSTAB with a multigrid preconditioner, and the
// projection of the velocity.
#include <utility>
#include <vector>

#include <Eigen/SparseCore>

#include "core/aggregation_multigrid.hpp"
#include "core/bicgstab.hpp"
#include "core/linear_solve.hpp"
#include "particles/cell_grid.hpp"
#include "sph/fields.hpp"
#include "sph/kernel_table.hpp"
#include "sph/parameters.hpp"

namespace partimix::sph {

class PressurePoisson {
 public:
  PressurePoisson(double tolerance, int max_iterations);

  // Fluid particles are [0, fluid_count) of the fields, with the predicted velocities and the
  // grid built at their predicted positions; walls the rest, with their own velocities. Writes
  // every particle's pressure (fluid and wall) and sets wall densities to rho0.
  // `kernel` weighs the wall extrapolation, `gradient_kernel` the Laplacian and divergence.
  LinearSolve solve(Fields& fields, std::size_t fluid_count, const CellGrid& grid,
                    const KernelTable& kernel, const KernelTable& gradient_kernel,
                    const Parameters& parameters, double dt);

  // The constant taken off the last solution without a free surface, which the next solve adds
  // to its first guess: part of a checkpoint, so that a resumed run solves as the whole one.
  double mean_offset() const { return mean_offset_; }
  void set_mean_offset(double offset) { mean_offset_ = offset; }

 private:
  // The rows one thread assembled: their (column, value) entries one row after the other, each
  // row's sorted by column, and where each row starts.
  struct ThreadRows {
    std::vector<std::pair<int, double>> entries;
    std::vector<std::pair<int, std::size_t>> starts;  // (row, its first entry)
    void close_row(int row, std::size_t first);
  };
  // add_fluid_row returns true for a Dirichlet row (p = 0 at a free surface).
  bool add_fluid_row(std::size_t i, const Fields& f, const CellGrid& grid,
                     const KernelTable& kernel, const Parameters& p, double dt, ThreadRows& rows);
  void add_wall_row(std::size_t w, const Fields& f, std::size_t fluid_count, const CellGrid& grid,
                    const KernelTable& kernel, const Parameters& p, ThreadRows& rows);
  void assemble(const Fields& f, std::size_t fluid_count, const CellGrid& grid,
                const KernelTable& kernel, const KernelTable& gradient_kernel, const Parameters& p,
                double dt);
  void lay_out_matrix(std::size_t n, std::size_t fluid_count);

  // Relative growth of a fluid row's diagonal without a free surface (docs/sph.md): below 1% of
  // the lowest mode of the discrete Laplacian, (pi dp / L)^2 of the diagonal, up to L = 300
  // spacings across.
  static constexpr double kRegularisation = 1e-6;
  // The multigrid's V-cycle drops couplings below this fraction of a row's largest onto the
  // diagonal (docs/sph.md, "The pressure solve", "Lumping the weak couplings").
  static constexpr double kLumpedFraction = 0.3;
  using Matrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;
  std::vector<ThreadRows> thread_rows_;
  Eigen::VectorXd rhs_;
  Eigen::VectorXd solution_;
  Matrix matrix_;
  AggregationMultigrid multigrid_{kLumpedFraction};
  Bicgstab solver_;
  bool has_dirichlet_row_ = false;
  double mean_offset_ = 0.0;  // the constant taken off the last solution: the next one's guess
};

// u_i -= dt sum_j m_j (p_i + p_j) / rho0^2 grad_i W_ij for the fluid particles (pressures of
// this instant, grid at the current positions).
void project_velocities(Fields& fields, std::size_t fluid_count, const CellGrid& grid,
                        const KernelTable& kernel, const Parameters& parameters, double dt);

}  // namespace partimix::sph
