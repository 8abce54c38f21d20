#pragma once
// LU factorisation with partial pivoting (Golub & Van Loan 2013, "Matrix computations",
// Algorithm 3.4.1) of a small sparse matrix held dense, for the coarsest level of
// core/aggregation_multigrid.hpp (at most a few hundred unknowns). Its storage is kept between
// factorisations, so that factoring a matrix no larger than the largest before allocates
// nothing; Eigen's SparseLU allocates its work space in every factorisation.
#include <vector>

#include <Eigen/SparseCore>

namespace partimix {

class DenseLu {
 public:
  using MatrixView = Eigen::Map<const Eigen::SparseMatrix<double, Eigen::RowMajor>>;

  // False when a pivot is exactly zero (a singular matrix): solve must not be called then.
  bool factor(const MatrixView& a);
  // x = A^-1 b for the matrix last factored; b and x hold its number of rows and may not alias.
  void solve(const double* b, double* x) const;

 private:
  Eigen::Index n_ = 0;
  std::vector<double> lu_;  // row-major: L below the diagonal (unit diagonal), U on and above
  std::vector<Eigen::Index> pivot_;  // row k was swapped with row pivot_[k] at step k
};

}  // namespace partimix
