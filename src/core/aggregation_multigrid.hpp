#pragma once
// An algebraic multigrid preconditioner by plain aggregation (docs/sph.md, "The pressure
// solve"), for Eigen's iterative solvers: Eigen::BiCGSTAB<Matrix, AggregationMultigrid>.
// Each level groups the unknowns into aggregates of strongly coupled neighbours (Vanek, Mandel
// & Brezina 1996, the three passes of their section 3), the coarse operator is the Galerkin
// product P^T A P with the piecewise-constant prolongation P, and one V-cycle with damped Jacobi
// smoothing and an over-corrected coarse step (Braess 1995) is the preconditioner's action; the
// coarsest level is solved by Eigen's SparseLU (by Jacobi sweeps if the aggregation stalls
// while it is still large, or if the factorisation fails). Eigen has no multigrid and Debian's
// hypre needs MPI, which partimix does not use yet; the setup is linear in the matrix's nonzeros,
// cheap enough to redo at every step of a particle method, where the matrix changes each step.
#include <memory>
#include <vector>

#include <Eigen/SparseCore>
#include <Eigen/SparseLU>

namespace partimix {

class AggregationMultigrid {
 public:
  using Matrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;
  using Vector = Eigen::VectorXd;

  AggregationMultigrid() = default;

  // The interface Eigen's iterative solvers call.
  template <class MatrixType>
  AggregationMultigrid& analyzePattern(const MatrixType&) {
    return *this;
  }
  template <class MatrixType>
  AggregationMultigrid& factorize(const MatrixType& a) {
    return compute(a);
  }
  template <class MatrixType>
  AggregationMultigrid& compute(const MatrixType& a) {
    setup(Matrix(a));
    return *this;
  }
  Vector solve(const Vector& b) const;
  // Always Success: a level that cannot be factored falls back to Jacobi sweeps.
  Eigen::ComputationInfo info() const { return Eigen::Success; }

  std::size_t levels() const { return levels_.size(); }
  // True when the coarsest level is solved by the direct factorisation (false when it was too
  // large or could not be factored, and Jacobi sweeps stand in).
  bool direct_coarsest() const { return coarsest_ != nullptr; }
  // Unknowns of level l (0 the finest).
  Eigen::Index size(std::size_t level) const { return levels_[level].a.rows(); }
  // The operator of level l.
  const Matrix& matrix(std::size_t level) const { return levels_[level].a; }

 private:
  struct Level {
    Matrix a;
    Vector inverse_diagonal;
    std::vector<int> aggregate;  // the coarse unknown of each unknown of this level
    mutable Vector x, b, r;      // work vectors of the V-cycle
  };

  void setup(Matrix a);
  void cycle(std::size_t level) const;
  void solve_coarsest(const Level& level) const;

  std::vector<Level> levels_;
  std::unique_ptr<Eigen::SparseLU<Eigen::SparseMatrix<double>>> coarsest_;
};

// `a` with each row's off-diagonal entries smaller in magnitude than `fraction` of the row's
// largest added to its diagonal: the row sums, and with them the constant vector a Laplacian
// leaves (nearly) unchanged, stay as they were, with far fewer entries for a wide stencil.
AggregationMultigrid::Matrix lump_weak_couplings(const AggregationMultigrid::Matrix& a,
                                                 double fraction);

}  // namespace partimix
