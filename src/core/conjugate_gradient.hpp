#pragma once
// The conjugate gradient method with a diagonal (Jacobi) preconditioner (Hestenes & Stiefel 1952;
// Saad 2003, "Iterative methods for sparse linear systems", Algorithm 9.1), for the implicit
// viscosity's symmetric positive definite systems (docs/sph.md, "Implicit viscosity"). The
// matrix is kept whole (both triangles, row-major, so that Eigen's product runs on every
// thread), and the work vectors between solves: solving a system of the size of the last one
// allocates nothing, where Eigen's ConjugateGradient allocates its vectors in every solve.
#include <Eigen/SparseCore>

#include "core/linear_solve.hpp"

namespace partimix {

class ConjugateGradient {
 public:
  using Matrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;
  using Vector = Eigen::VectorXd;

  ConjugateGradient(double tolerance, int max_iterations);

  // The preconditioner of `a`, 1 / a_ii (1 where a_ii = 0), for the solves that follow.
  void compute(const Matrix& a);
  // a x = b from the guess in x, until |b - a x| <= tolerance |b| (the recurrence's residual)
  // or max_iterations; x = 0 for b = 0. A guess whose residual exceeds |b| is dropped for
  // x = 0, as in core/bicgstab.hpp (b at round-off, the guess the last O(1) solution).
  LinearSolve solve(const Matrix& a, const Eigen::Ref<const Vector>& b, Vector& x);

 private:
  double tolerance_;
  int max_iterations_;
  Vector inverse_diagonal_, r_, z_, p_, q_;
};

}  // namespace partimix
