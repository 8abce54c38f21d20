#pragma once
// An algebraic multigrid preconditioner by plain aggregation (docs/sph.md, "The pressure
// solve"), for core/bicgstab.hpp (and Eigen's iterative solvers, Eigen::BiCGSTAB<Matrix,
// AggregationMultigrid>, through the interface they call).
// Each level groups the unknowns into aggregates of strongly coupled neighbours (Vanek, Mandel
// & Brezina 1996, the three passes of their section 3), the coarse operator is the Galerkin
// product P^T A P with the piecewise-constant prolongation P, and one V-cycle with damped Jacobi
// smoothing and an over-corrected coarse step (Braess 1995) is the preconditioner's action; the
// coarsest level is solved directly (core/dense_lu.hpp up to kCoarsestSize unknowns, Eigen's
// SparseLU above, where the aggregation stalled; Jacobi sweeps if it stalls while still large,
// or if the factorisation fails). Eigen has no multigrid and Debian's hypre needs MPI, which
// partimix does not use yet; the setup is linear in the matrix's nonzeros, cheap enough to redo
// at every step of a particle method, where the matrix changes each step. The levels keep their
// buffers between set-ups, so that once they are as large as a set-up needs, neither the set-up
// (but for SparseLU's) nor a V-cycle allocates.
#include <memory>
#include <vector>

#include <Eigen/SparseCore>
#include <Eigen/SparseLU>

#include "core/dense_lu.hpp"
#include "core/preconditioner.hpp"

namespace partimix {

class AggregationMultigrid : public Preconditioner {
 public:
  using Matrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;
  using MatrixView = Eigen::Map<const Matrix>;
  using Vector = Eigen::VectorXd;

  // `lumped_fraction` > 0: the V-cycle works on the finest operator with each row's
  // off-diagonal entries below that fraction of the row's largest lumped onto its diagonal
  // (lump_weak_couplings; for the SPH Laplacian's wide stencil). 0: the operator as it is, as
  // for a grid's 7-point operator, whose weak couplings (across a density jump, through a
  // partly blocked face) may carry most of the solution's change (docs/sph.md, "The pressure
  // solve").
  explicit AggregationMultigrid(double lumped_fraction = 0.0) : lumped_fraction_(lumped_fraction) {}

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
    return compute(Matrix(a));
  }
  AggregationMultigrid& compute(const Matrix& a);
  Vector solve(const Vector& b) const;
  // Always Success: a level that cannot be factored falls back to Jacobi sweeps.
  Eigen::ComputationInfo info() const { return Eigen::Success; }

  // One V-cycle: out = M^-1 in.
  void apply(const Vector& in, Vector& out) const override;

  std::size_t levels() const { return level_count_; }
  // True when the coarsest level is solved by a direct factorisation (false when it was too
  // large or could not be factored, and Jacobi sweeps stand in).
  bool direct_coarsest() const { return coarsest_ != Coarsest::jacobi; }
  // Unknowns of level l (0 the finest).
  Eigen::Index size(std::size_t level) const { return levels_[level].rows; }
  // The operator of level l.
  MatrixView matrix(std::size_t level) const { return levels_[level].view(); }

 private:
  // A level's operator in compressed rows, and its V-cycle's vectors: std::vectors, whose
  // capacity a smaller set-up keeps.
  struct Level {
    Eigen::Index rows = 0;
    std::vector<int> start, column;
    std::vector<double> value;
    std::vector<int> aggregate;  // the coarse unknown of each unknown of this level, or < 0
    std::vector<double> inverse_diagonal;
    mutable std::vector<double> x, b, r;
    MatrixView view() const;
    void begin(Eigen::Index n);  // empties the operator for n rows, appended in order
    void append(int col, double entry) {
      column.push_back(col);
      value.push_back(entry);
    }
    void end_row() { start.push_back(static_cast<int>(column.size())); }
    void size_vectors();
  };
  enum class Coarsest { dense, sparse, jacobi };

  void lump(const Matrix& a);
  int aggregate(Level& level);
  void galerkin(const Level& fine, int count, Level& coarse);
  void factor_coarsest();
  void cycle(std::size_t level) const;
  void solve_coarsest(const Level& level) const;

  double lumped_fraction_;
  std::vector<Level> levels_;  // [0, level_count_) in use; the rest keep their buffers
  std::size_t level_count_ = 0;
  Coarsest coarsest_ = Coarsest::jacobi;
  DenseLu dense_;
  std::unique_ptr<Eigen::SparseLU<Eigen::SparseMatrix<double>>> sparse_;
  // Scratch of the set-up, kept: the aggregation's second pass, the Galerkin product's members
  // of each aggregate and its row being gathered, the lumping's row.
  std::vector<int> joined_, first_, members_, next_, slot_row_;
  std::vector<std::size_t> slot_;
  std::vector<std::pair<int, double>> row_entries_;
};

// `a` with each row's off-diagonal entries smaller in magnitude than `fraction` of the row's
// largest added to its diagonal: the row sums, and with them the constant vector a Laplacian
// leaves (nearly) unchanged, stay as they were, with far fewer entries for a wide stencil.
AggregationMultigrid::Matrix lump_weak_couplings(const AggregationMultigrid::Matrix& a,
                                                 double fraction);

}  // namespace partimix
