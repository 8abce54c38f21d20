#pragma once
// BiCGSTAB with right preconditioning (van der Vorst 1992, SIAM J. Sci. Stat. Comput. 13(2),
// 631-644, the preconditioned algorithm of section 4), for the incompressible scheme's pressure
// solve (docs/sph.md, "The pressure solve"). Its work vectors are kept between solves, so that
// solving a system of the size of the last one allocates nothing: Eigen's BiCGSTAB allocates
// nine vectors in every solve, and the hot loop must not allocate (DESIGN.md).
#include <Eigen/SparseCore>

#include "core/linear_solve.hpp"
#include "core/preconditioner.hpp"

namespace partimix {

class Bicgstab {
 public:
  using Matrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;
  using Vector = Eigen::VectorXd;

  Bicgstab(double tolerance, int max_iterations);

  // a x = b from the guess in x, until |b - a x| <= tolerance |b| (the recurrence's residual,
  // as Eigen's) or max_iterations; x = 0 for b = 0. A guess whose residual exceeds |b| is
  // dropped for x = 0: when b falls to round-off (a fluid come to rest), the last solution as
  // the guess would leave a residual that no iteration can bring below tolerance |b|, while
  // from zero the reduction is relative and so reachable whatever the scale of b.
  LinearSolve solve(const Matrix& a, const Preconditioner& m, const Vector& b, Vector& x);

 private:
  // The true residual as the new shadow vector r0, and the directions cleared: where r0 and the
  // residual have become orthogonal, or a step would divide by zero.
  void restart(const Matrix& a, const Vector& b, const Vector& x);

  double tolerance_;
  int max_iterations_;
  double rho_ = 1.0;
  double alpha_ = 1.0;
  double omega_ = 1.0;
  Vector r_, shadow_, p_, v_, s_, t_, y_, z_;
};

}  // namespace partimix
