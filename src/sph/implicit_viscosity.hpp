#pragma once
// Backward-Euler viscous prediction of the incompressible scheme (docs/sph.md, "Implicit
// viscosity"): u* - dt L(u*) = u^n + dt g with L the Morris operator, walls through their held
// no-slip ghost velocities; one symmetric positive-definite system per velocity component,
// solved by the conjugate gradient method (core/conjugate_gradient.hpp). The pairs and their kernel
// factors are gathered once per step (gather_pairs); each Picard solve of the step only refills the
// matrix's values in place.
#include <cstdint>
#include <span>
#include <vector>

#include <Eigen/SparseCore>

#include "core/conjugate_gradient.hpp"
#include "core/linear_solve.hpp"
#include "particles/cell_grid.hpp"
#include "sph/fields.hpp"
#include "sph/kernel_table.hpp"
#include "sph/parameters.hpp"

namespace partimix::sph {

class ImplicitViscosity {
 public:
  ImplicitViscosity(double tolerance, int max_iterations);

  // Fluid particles are [0, fluid_count) of the fields, at x^n; the grid built there. Gathers
  // each fluid particle's partners and the factors m_j (-r_ij . grad W_ij) / (rho0^2 (r^2 +
  // eta^2)) of its pair coefficients (with `gradient_kernel`), the kernel values W_iw of its wall
  // partners (with `kernel`, the wall state's), and lays out the matrix.
  void gather_pairs(const Fields& fields, std::size_t fluid_count, const CellGrid& grid,
                    const KernelTable& kernel, const KernelTable& gradient_kernel,
                    const Parameters& parameters);
  // With the fluid's apparent viscosities of now; `start` holds u^n, `explicit_acceleration`
  // (empty or one per fluid particle) what the step adds to g explicitly, the stress form's
  // div(eta G^T) / rho. Writes u* into the fluid particles' velocities.
  LinearSolve solve(Fields& fields, std::size_t fluid_count, const Parameters& parameters,
                    const std::vector<Vec3>& start, std::span<const Vec3> explicit_acceleration,
                    double dt);

 private:
  struct Partner {
    std::uint32_t index;  // a fluid particle's (the row's own for the diagonal) or a wall's
    double factor;        // the pair coefficient over the pair viscosity; 0 on the diagonal
    double weight;        // a wall's kernel value W_iw; 0 for the fluid
  };
  void gather_row(std::size_t i, const Fields& f, const CellGrid& grid, const KernelTable& kernel,
                  const KernelTable& gradient_kernel, const Parameters& p,
                  std::vector<Partner>& out);
  void lay_out_matrix(std::size_t fluid_count);
  void fill_row(std::size_t i, const Fields& f, const Parameters& p, const Vec3& start,
                const Vec3& acceleration, double dt);

  using Matrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;
  // Row i's fluid partners and diagonal, in column order: partners_[row_start_[i],
  // wall_start_[i]); its wall partners: [wall_start_[i], row_start_[i + 1]).
  std::vector<Partner> partners_;
  std::vector<std::size_t> row_start_;
  std::vector<std::size_t> wall_start_;
  std::vector<std::vector<Partner>> thread_partners_;
  Eigen::MatrixX3d rhs_;
  Eigen::VectorXd component_;
  Matrix matrix_;
  ConjugateGradient solver_;
};

}  // namespace partimix::sph
