// partimix's own linear solvers (docs/sph.md, "The pressure solve", last paragraph): BiCGSTAB
// (core/bicgstab.hpp), the conjugate gradient method (core/conjugate_gradient.hpp) and the dense
// LU of the multigrid's coarsest level (core/dense_lu.hpp), each against Eigen's direct solvers
// on systems whose answer those give to round-off. The iterative solvers are asked for a relative
// residual of 1e-10, so their answers must agree with the direct ones within 1e-8 of the
// answer's largest value (the systems' condition numbers are below 1e3); the LU within 1e-12.
#include <gtest/gtest.h>

#include <cmath>

#include <Eigen/Dense>
#include <Eigen/SparseLU>

#include "core/aggregation_multigrid.hpp"
#include "core/bicgstab.hpp"
#include "core/conjugate_gradient.hpp"
#include "core/dense_lu.hpp"

namespace partimix {
namespace {

using Matrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;
using Vector = Eigen::VectorXd;

// -u'' + c u' on n points with u = 0 beyond both ends, central differences: symmetric for c = 0,
// not for c != 0 (the convection-diffusion matrix BiCGSTAB is made for).
Matrix convection_diffusion(int n, double c) {
  std::vector<Eigen::Triplet<double>> entries;
  for (int i = 0; i < n; ++i) {
    entries.emplace_back(i, i, 2.0);
    if (i > 0)
      entries.emplace_back(i, i - 1, -1.0 - c / 2.0);
    if (i + 1 < n)
      entries.emplace_back(i, i + 1, -1.0 + c / 2.0);
  }
  Matrix a(n, n);
  a.setFromTriplets(entries.begin(), entries.end());
  return a;
}

Vector direct_solution(const Matrix& a, const Vector& b) {
  Eigen::SparseLU<Eigen::SparseMatrix<double>> lu(a);
  return lu.solve(b);
}

class Identity : public Preconditioner {
 public:
  void apply(const Vector& in, Vector& out) const override { out = in; }
};

TEST(Bicgstab, SolvesANonsymmetricSystemAsTheDirectSolverDoes) {
  const Matrix a = convection_diffusion(30, 0.8);
  const Vector b = Vector::LinSpaced(a.rows(), -1.0, 2.0);
  const Vector exact = direct_solution(a, b);
  Bicgstab solver(1e-10, 1000);
  Vector x = Vector::Zero(a.rows());
  const LinearSolve result = solver.solve(a, Identity(), b, x);
  EXPECT_TRUE(result.converged);
  EXPECT_LE(result.residual, 1e-10);
  // The residual reported is BiCGSTAB's recurrence; the true one departs from it by round-off,
  // of order iterations x machine epsilon x |A| |x| (some 1e-13 |b| here), so it must meet the
  // tolerance to within 1e-12 |b|.
  EXPECT_LE((b - a * x).norm(), (1e-10 + 1e-12) * b.norm());
  EXPECT_LT((x - exact).lpNorm<Eigen::Infinity>(), 1e-8 * exact.lpNorm<Eigen::Infinity>());
}

// With the multigrid as its preconditioner, from a guess, and a second time on the same system
// (the kept work vectors must not carry anything over).
TEST(Bicgstab, SolvesWithTheMultigridFromAGuessAndAgain) {
  const Matrix a = convection_diffusion(2000, 0.3);
  const Vector b = Vector::LinSpaced(a.rows(), -1.0, 2.0);
  const Vector exact = direct_solution(a, b);
  AggregationMultigrid multigrid;
  multigrid.compute(a);
  Bicgstab solver(1e-10, 1000);
  for (int attempt = 0; attempt < 2; ++attempt) {
    Vector x = Vector::Constant(a.rows(), 0.5);
    const LinearSolve result = solver.solve(a, multigrid, b, x);
    EXPECT_TRUE(result.converged) << "attempt " << attempt;
    EXPECT_LT((x - exact).lpNorm<Eigen::Infinity>(), 1e-8 * exact.lpNorm<Eigen::Infinity>());
  }
}

TEST(Bicgstab, ReportsFailureWhenTheIterationsRunOut) {
  const Matrix a = convection_diffusion(200, 0.5);
  const Vector b = Vector::Ones(a.rows());
  Bicgstab solver(1e-12, 3);
  Vector x = Vector::Zero(a.rows());
  const LinearSolve result = solver.solve(a, Identity(), b, x);
  EXPECT_FALSE(result.converged);
  EXPECT_EQ(result.iterations, 3);
  EXPECT_GT(result.residual, 1e-12);
}

TEST(Bicgstab, AZeroRightHandSideGivesZero) {
  const Matrix a = convection_diffusion(10, 0.5);
  Bicgstab solver(1e-10, 100);
  Vector x = Vector::Ones(a.rows());
  const LinearSolve result = solver.solve(a, Identity(), Vector::Zero(a.rows()), x);
  EXPECT_TRUE(result.converged);
  EXPECT_EQ(result.iterations, 0);
  EXPECT_EQ(x.norm(), 0.0);
}

// b at round-off (1e-17) with the last solution of an O(1) system as the guess, as a pressure
// correction sees when the fluid comes to rest (two layers under gravity): from that guess the
// residual cannot fall below 1e-10 |b|; the solver drops it for zero and converges.
TEST(Bicgstab, ARoundOffRightHandSideConvergesDespiteALargeGuess) {
  const Matrix a = convection_diffusion(200, 0.3);
  const Vector b = 1e-17 * Vector::LinSpaced(a.rows(), -1.0, 2.0);
  AggregationMultigrid multigrid;
  multigrid.compute(a);
  Bicgstab solver(1e-10, 1000);
  Vector x = Vector::Constant(a.rows(), 3.0);
  const LinearSolve result = solver.solve(a, multigrid, b, x);
  EXPECT_TRUE(result.converged) << result.residual;
  const Vector exact = direct_solution(a, b);
  EXPECT_LT((x - exact).lpNorm<Eigen::Infinity>(), 1e-8 * exact.lpNorm<Eigen::Infinity>());
}

// A symmetric positive-definite system with a varying diagonal (the implicit viscosity's kind):
// I + k (1D Laplacian) with k growing along the rows.
TEST(ConjugateGradient, SolvesASymmetricPositiveDefiniteSystemAsTheDirectSolverDoes) {
  const int n = 300;
  std::vector<Eigen::Triplet<double>> entries;
  for (int i = 0; i < n; ++i) {
    const double k = 1.0 + 50.0 * i / n;
    entries.emplace_back(i, i, 1.0 + 2.0 * k);
    if (i > 0)
      entries.emplace_back(i, i - 1, -k);
    if (i + 1 < n)
      entries.emplace_back(i, i + 1, -k);
  }
  Matrix a(n, n);
  a.setFromTriplets(entries.begin(), entries.end());
  const Matrix symmetric = (Matrix(a.transpose()) + a) / 2.0;
  const Vector b = Vector::LinSpaced(n, 1.0, -3.0);
  const Vector exact = direct_solution(symmetric, b);
  ConjugateGradient solver(1e-10, 1000);
  solver.compute(symmetric);
  Vector x = Vector::Zero(n);
  const LinearSolve result = solver.solve(symmetric, b, x);
  EXPECT_TRUE(result.converged);
  EXPECT_LE(result.residual, 1e-10);
  EXPECT_LT((x - exact).lpNorm<Eigen::Infinity>(), 1e-8 * exact.lpNorm<Eigen::Infinity>());
}

// The round-off right-hand side of a fluid at rest from the last O(1) solution as the guess (see
// Bicgstab's test): the guess is dropped for zero and the solve converges.
TEST(ConjugateGradient, ARoundOffRightHandSideConvergesDespiteALargeGuess) {
  const int n = 100;
  std::vector<Eigen::Triplet<double>> entries;
  for (int i = 0; i < n; ++i) {
    entries.emplace_back(i, i, 3.0);
    if (i > 0)
      entries.emplace_back(i, i - 1, -1.0);
    if (i + 1 < n)
      entries.emplace_back(i, i + 1, -1.0);
  }
  Matrix a(n, n);
  a.setFromTriplets(entries.begin(), entries.end());
  const Vector b = 1e-17 * Vector::LinSpaced(n, 1.0, -3.0);
  ConjugateGradient solver(1e-10, 1000);
  solver.compute(a);
  Vector x = Vector::Constant(n, 2.0);
  const LinearSolve result = solver.solve(a, b, x);
  EXPECT_TRUE(result.converged) << result.residual;
  const Vector exact = direct_solution(a, b);
  EXPECT_LT((x - exact).lpNorm<Eigen::Infinity>(), 1e-8 * exact.lpNorm<Eigen::Infinity>());
}

// A matrix that needs row exchanges (a zero first pivot) against Eigen's dense LU; a singular
// one is refused.
TEST(DenseLu, SolvesAsEigensLuDoesAndRefusesASingularMatrix) {
  const int n = 40;
  Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j)
      dense(i, j) = (i == j ? 0.5 * n : 0.0) + std::sin(1.0 + i * 0.7 + j * 1.3);
  }
  dense(0, 0) = 0.0;
  const Matrix a = dense.sparseView();
  const Vector b = Vector::LinSpaced(n, -2.0, 5.0);
  const Vector exact = dense.partialPivLu().solve(b);
  DenseLu lu;
  ASSERT_TRUE(lu.factor(DenseLu::MatrixView(a.rows(), a.cols(), a.nonZeros(), a.outerIndexPtr(),
                                            a.innerIndexPtr(), a.valuePtr())));
  Vector x(n);
  lu.solve(b.data(), x.data());
  EXPECT_LT((x - exact).lpNorm<Eigen::Infinity>(), 1e-12 * exact.lpNorm<Eigen::Infinity>());

  Eigen::MatrixXd singular = dense;
  singular.col(7).setZero();
  const Matrix s = singular.sparseView();
  EXPECT_FALSE(lu.factor(DenseLu::MatrixView(s.rows(), s.cols(), s.nonZeros(), s.outerIndexPtr(),
                                             s.innerIndexPtr(), s.valuePtr())));
}

}  // namespace
}  // namespace partimix
