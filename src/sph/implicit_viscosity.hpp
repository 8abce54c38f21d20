#pragma once
// Backward-Euler viscous prediction of the incompressible scheme (docs/sph.md, "Implicit
// viscosity"): u* - dt L(u*) = u^n + dt g with L the Morris operator, walls through their held
// no-slip ghost velocities; one symmetric positive-definite system per velocity component,
// solved by Eigen's conjugate gradient.
#include <vector>

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCore>

#include "particles/cell_grid.hpp"
#include "sph/fields.hpp"
#include "sph/kernel_table.hpp"
#include "sph/linear_solve.hpp"
#include "sph/parameters.hpp"

namespace partimix::sph {

class ImplicitViscosity {
 public:
  ImplicitViscosity(double tolerance, int max_iterations);

  // Fluid particles are [0, fluid_count) of the fields, at x^n with their apparent viscosities;
  // `start` holds u^n. Writes u* into the fluid particles' velocities.
  LinearSolve solve(Fields& fields, std::size_t fluid_count, const CellGrid& grid,
                    const KernelTable& gradient_kernel, const Parameters& parameters,
                    const std::vector<Vec3>& start, double dt);

 private:
  void add_row(std::size_t i, const Fields& f, std::size_t fluid_count, const CellGrid& grid,
               const KernelTable& kernel, const Parameters& p, const Vec3& start, double dt);

  using Matrix = Eigen::SparseMatrix<double>;
  std::vector<Eigen::Triplet<double>> entries_;
  Eigen::MatrixX3d rhs_;
  Eigen::VectorXd component_;
  Matrix matrix_;
  Eigen::ConjugateGradient<Matrix, Eigen::Lower | Eigen::Upper,
                           Eigen::DiagonalPreconditioner<double>>
      solver_;
};

}  // namespace partimix::sph
