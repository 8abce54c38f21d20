#pragma once
// The pressure correction of a grid fluid's step (docs/cfd.md, "One time step", steps 2 and 3):
// on the open cells, with w_f = ε_f a_f A_f / h over each open face f between cells c and n,
//
//     Σ_f w_f (φ_c - φ_n) = -(Σ_f ±ε_f u*_f A_f + V_c s_c)      (± outward, s = Δε/Δt)
//
// then u_f = u*_f - a_f (φ_above - φ_below) / h on the open faces, so that the discrete
// continuity equation Σ_f ±ε_f u_f A_f + V_c s_c = 0 holds in every open cell to the solver's
// tolerance. An outlet face of a cell (p = 0 on the side, half a cell away) adds 2 w_f φ_c to its
// row and is corrected by u_f = u*_f ∓ a_f φ_c / (h/2). Each connected region of open cells
// without an outlet has a pressure level of its own: one cell of each is held at φ = 0 and left
// out of the unknowns, and the region's right-hand side loses its mean first (round-off, or an
// imbalance of the sources, which `imbalance()` reports), so the system is symmetric positive
// definite. Solved by BiCGSTAB with
// the aggregation multigrid (core/bicgstab.hpp, core/aggregation_multigrid.hpp). The matrix's
// pattern is laid out once per mask; each step refills its values and allocates nothing. Should
// BiCGSTAB not converge within max_iterations, the system is factorised instead (Eigen's
// SimplicialLDLT, the matrix being symmetric positive definite): the first step of two phases
// at rest, whose correction must build the whole hydrostatic pressure across a density jump of a
// thousand, took BiCGSTAB 2,033 iterations on 20 x 20 cells (and some 20 on 40 x 40 or in later
// steps). Only that fallback allocates.
#include <cstdint>
#include <utility>
#include <vector>

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include "cfd/flow_mask.hpp"
#include "core/aggregation_multigrid.hpp"
#include "core/bicgstab.hpp"
#include "core/linear_solve.hpp"
#include "core/sparse_pattern.hpp"
#include "grid/staggered_grid.hpp"

namespace partimix::cfd {

class PressureProjection {
 public:
  PressureProjection(double tolerance, int max_iterations);

  // Numbers the open cells, finds the regions and lays out the matrix's pattern.
  void lay_out(const grid::StaggeredGrid& grid, const FlowMask& mask);

  // Solves for φ (one value per cell, 0 on closed and held cells) and corrects `velocity` on the
  // open faces. void_fraction: ε_f on every face; coefficient: a_f on the open faces; source: s_c
  // per cell.
  LinearSolve project(const grid::StaggeredGrid& grid, const FlowMask& mask,
                      const FaceArrays& void_fraction, const FaceArrays& coefficient,
                      const std::vector<double>& source, FaceArrays& velocity,
                      std::vector<double>& correction);

  // The first guess of the next solve from a φ per cell (the last step's, on a restore).
  void set_guess(const std::vector<double>& correction);

  // The largest |mean right-hand side| of a region in the last solve, per unit volume [1/s].
  double imbalance() const { return imbalance_; }

 private:
  struct FaceTerm {
    int axis;
    std::size_t face;
    int diagonal;      // the slot of the row's own column
    int off_diagonal;  // the slot of the neighbour's column, or -1 for a held neighbour
    bool outlet;       // an outlet face: φ = 0 half a cell away
  };
  void find_regions(const grid::StaggeredGrid& grid, const FlowMask& mask);
  void lay_out_row(const grid::StaggeredGrid& grid, const FlowMask& mask, int i, int j, int k);
  void fill_matrix(const grid::StaggeredGrid& grid, const FaceArrays& void_fraction,
                   const FaceArrays& coefficient);
  void fill_rhs(const grid::StaggeredGrid& grid, const FaceArrays& void_fraction,
                const std::vector<double>& source, const FaceArrays& velocity);
  void correct(const grid::StaggeredGrid& grid, const FlowMask& mask, const FaceArrays& coefficient,
               const std::vector<double>& correction, FaceArrays& velocity) const;

  // The factorised solve of the system as filled, after BiCGSTAB's failure `iterative`.
  LinearSolve solve_directly(const LinearSolve& iterative);

  double tolerance_;
  Bicgstab solver_;
  AggregationMultigrid multigrid_;
  Eigen::SparseMatrix<double, Eigen::RowMajor> matrix_;
  Eigen::VectorXd rhs_, solution_;
  std::vector<std::int64_t> unknown_;  // per cell: its row, -1 closed, -2 held
  std::vector<std::size_t> row_cell_;
  std::vector<int> region_;  // per cell: its region, -1 closed
  std::vector<double> region_sum_;
  std::vector<double> region_volume_;
  std::vector<std::uint8_t> region_outlet_;  // per region: it has an outlet face
  SparsePattern pattern_;
  std::vector<std::pair<std::int64_t, int>> entries_;  // a row's (column, slot id) while laid out
  std::vector<int> slots_;
  std::vector<FaceTerm> terms_;
  std::vector<double> cell_rhs_;
  double imbalance_ = 0.0;
};

}  // namespace partimix::cfd
