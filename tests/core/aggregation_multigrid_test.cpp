// The aggregation multigrid preconditioner (core/aggregation_multigrid.hpp, docs/sph.md "The
// pressure solve") on the 7-point Laplacian of a cube with p = 0 on its faces, whose BiCGSTAB
// iterations with Jacobi grow with the grid: the solution must be conjugate gradient's at the
// tolerance 1e-13 (within 1e-6 of its largest value, asked for 1e-8), the multigrid's iterations
// must not grow by more than half from 16^3 to 32^3 unknowns, and stay under a third of Jacobi's.
// Measured (2026-11-27): 16^3 12 iterations (Jacobi 39), 32^3 15 (Jacobi 75).
#include <gtest/gtest.h>

#include <cmath>

#include <Eigen/IterativeLinearSolvers>

#include "core/aggregation_multigrid.hpp"
#include "core/bicgstab.hpp"

namespace partimix {
namespace {

using Matrix = AggregationMultigrid::Matrix;

Matrix laplacian(int n) {
  std::vector<Eigen::Triplet<double>> entries;
  auto index = [n](int i, int j, int k) { return (k * n + j) * n + i; };
  for (int k = 0; k < n; ++k) {
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) {
        const int row = index(i, j, k);
        entries.emplace_back(row, row, 6.0);
        const int neighbours[6][3] = {{i - 1, j, k}, {i + 1, j, k}, {i, j - 1, k},
                                      {i, j + 1, k}, {i, j, k - 1}, {i, j, k + 1}};
        for (const auto& c : neighbours) {
          if (c[0] >= 0 && c[0] < n && c[1] >= 0 && c[1] < n && c[2] >= 0 && c[2] < n)
            entries.emplace_back(row, index(c[0], c[1], c[2]), -1.0);
        }
      }
    }
  }
  Matrix a(n * n * n, n * n * n);
  a.setFromTriplets(entries.begin(), entries.end());
  return a;
}

template <class Preconditioner>
int iterations_to_solve(const Matrix& a, const Eigen::VectorXd& b, Eigen::VectorXd& x) {
  Eigen::BiCGSTAB<Matrix, Preconditioner> solver;
  solver.setTolerance(1e-8);
  solver.compute(a);
  x = solver.solve(b);
  EXPECT_EQ(solver.info(), Eigen::Success);
  return static_cast<int>(solver.iterations());
}

// The same with partimix's BiCGSTAB and the multigrid lumping couplings below `lumped_fraction`.
int multigrid_iterations_to_solve(const Matrix& a, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                                  double lumped_fraction) {
  AggregationMultigrid multigrid(lumped_fraction);
  multigrid.compute(a);
  Bicgstab solver(1e-8, 1000);
  x.setZero(a.rows());
  const LinearSolve result = solver.solve(a, multigrid, b, x);
  EXPECT_TRUE(result.converged);
  return result.iterations;
}

// Solves a x = b with the multigrid (lumping couplings below `lumped_fraction`) and with Jacobi:
// the multigrid's answer must be conjugate gradient's, in under a third of Jacobi's iterations.
int multigrid_iterations(const Matrix& a, const char* label, double lumped_fraction = 0.0) {
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(a.rows(), -1.0, 2.0);
  Eigen::VectorXd x;
  const int multigrid = multigrid_iterations_to_solve(a, b, x, lumped_fraction);
  Eigen::VectorXd jacobi_x;
  const int jacobi = iterations_to_solve<Eigen::DiagonalPreconditioner<double>>(a, b, jacobi_x);
  Eigen::ConjugateGradient<Matrix, Eigen::Lower | Eigen::Upper> reference;
  reference.setTolerance(1e-13);
  const Eigen::VectorXd exact = reference.compute(a).solve(b);
  std::printf("%s: multigrid %d iterations, Jacobi %d\n", label, multigrid, jacobi);
  EXPECT_LT((x - exact).lpNorm<Eigen::Infinity>(), 1e-6 * exact.lpNorm<Eigen::Infinity>());
  EXPECT_LT(3 * multigrid, jacobi);
  return multigrid;
}

TEST(AggregationMultigrid, SolvesThePoissonEquationInIterationsThatHardlyGrowWithTheGrid) {
  const int coarse = multigrid_iterations(laplacian(16), "16^3");
  const int fine = multigrid_iterations(laplacian(32), "32^3");
  EXPECT_LE(fine, coarse + coarse / 2);
}

TEST(AggregationMultigrid, BuildsLevelsThatShrinkToTheDirectSolve) {
  AggregationMultigrid multigrid;
  multigrid.compute(laplacian(32));
  ASSERT_GE(multigrid.levels(), 2U);
  for (std::size_t l = 1; l < multigrid.levels(); ++l)
    EXPECT_LT(multigrid.size(l), multigrid.size(l - 1) / 2);
  EXPECT_LE(multigrid.size(multigrid.levels() - 1), 500);
}

// The Galerkin product P^T A P with a piecewise-constant P keeps the sum of all entries
// (1^T P^T A P 1 = 1^T A 1, since P 1 = 1) and the symmetry of A on every level. The Laplacian
// with p = 0 on the faces has its entries' sum in its boundary rows: 6 n^2 here. Both hold to
// round-off of the sums (bounds 1e-9 and 1e-12 relative, some 1e3 times double's epsilon).
TEST(AggregationMultigrid, CoarseOperatorsKeepTheSumAndSymmetryOfTheMatrix) {
  AggregationMultigrid multigrid;
  multigrid.compute(laplacian(24));
  ASSERT_GE(multigrid.levels(), 3U);
  for (std::size_t l = 0; l < multigrid.levels(); ++l) {
    const Matrix& a = multigrid.matrix(l);
    EXPECT_NEAR(a.sum(), 6.0 * 24 * 24, 1e-9 * 6.0 * 24 * 24) << "level " << l;
    const Matrix asymmetry = a - Matrix(a.transpose());
    EXPECT_LE(asymmetry.cwiseAbs().sum(), 1e-12 * a.cwiseAbs().sum()) << "level " << l;
  }
}

// A diagonal matrix has no couplings to aggregate: the levels stop at once, above the size
// solved directly, and Jacobi sweeps stand in for the direct solve.
TEST(AggregationMultigrid, FallsBackToJacobiWhenNothingCoarsens) {
  const Eigen::Index n = 30000;
  Matrix a(n, n);
  std::vector<Eigen::Triplet<double>> entries;
  for (Eigen::Index i = 0; i < n; ++i)
    entries.emplace_back(static_cast<int>(i), static_cast<int>(i),
                         1.0 + static_cast<double>(i % 7));
  a.setFromTriplets(entries.begin(), entries.end());
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1.0, 2.0);
  Eigen::VectorXd x;
  iterations_to_solve<AggregationMultigrid>(a, b, x);
  EXPECT_LT((a * x - b).norm(), 1e-8 * b.norm());
}

// A matrix the direct solve cannot factor (here a 1D Laplacian with one unknown that has no
// entry at all; what made the vessel's coarsest level unfactorable is not known, since the
// SPH pressure rows always hold their diagonal) must not be used: the coarsest level falls back to
// Jacobi sweeps, whose zero diagonal passes nothing, and BiCGSTAB solves the consistent system.
// Before this fallback the solve read the failed factorisation and the run stopped with a
// segmentation fault (issue 18: the vessel at dp = 5 mm, Re = 10).
TEST(AggregationMultigrid, FallsBackToJacobiWhenTheDirectSolveFails) {
  const int n = 40;
  const int isolated = 17;
  std::vector<Eigen::Triplet<double>> entries;
  for (int i = 0; i < n; ++i) {
    if (i == isolated)
      continue;
    entries.emplace_back(i, i, 2.0);
    for (const int j : {i - 1, i + 1}) {
      if (j >= 0 && j < n && j != isolated)
        entries.emplace_back(i, j, -1.0);
    }
  }
  Matrix a(n, n);
  a.setFromTriplets(entries.begin(), entries.end());
  Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1.0, 2.0);
  b[isolated] = 0.0;
  AggregationMultigrid multigrid;
  multigrid.compute(a);
  EXPECT_FALSE(multigrid.direct_coarsest());
  EXPECT_TRUE(multigrid.solve(b).allFinite());
  Eigen::BiCGSTAB<Matrix, AggregationMultigrid> solver;
  solver.setTolerance(1e-10);
  const Eigen::VectorXd x = solver.compute(a).solve(b);
  EXPECT_EQ(solver.info(), Eigen::Success);
  EXPECT_LT((a * x - b).norm(), 1e-8 * b.norm());
}

// The SPH pressure matrix's stencil: every lattice neighbour within 3 spacings (the support
// 2h at h = 1.5 dp), weighted as the Wendland C2 kernel's -W'(r)/r, (1 - r/3)^3, with p = 0
// beyond the cube's faces (each row's diagonal the whole sum of its weights). 92 neighbours a
// row inside.
Matrix wide_stencil_laplacian(int n) {
  std::vector<Eigen::Triplet<double>> entries;
  auto index = [n](int i, int j, int k) { return (k * n + j) * n + i; };
  for (int k = 0; k < n; ++k) {
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) {
        double diagonal = 0.0;
        for (int dk = -3; dk <= 3; ++dk) {
          for (int dj = -3; dj <= 3; ++dj) {
            for (int di = -3; di <= 3; ++di) {
              const double r = std::sqrt(di * di + dj * dj + dk * dk);
              if (r == 0.0 || r >= 3.0)
                continue;
              const double weight = std::pow(1.0 - r / 3.0, 3);
              diagonal += weight;
              const int ii = i + di;
              const int jj = j + dj;
              const int kk = k + dk;
              if (ii >= 0 && ii < n && jj >= 0 && jj < n && kk >= 0 && kk < n)
                entries.emplace_back(index(i, j, k), index(ii, jj, kk), -weight);
            }
          }
        }
        entries.emplace_back(index(i, j, k), index(i, j, k), diagonal);
      }
    }
  }
  Matrix a(n * n * n, n * n * n);
  a.setFromTriplets(entries.begin(), entries.end());
  return a;
}

// Lumping keeps each row's sum to round-off, keeps exactly the entries at or above the fraction
// of the row's largest off-diagonal one (here 18 of the 92 neighbours inside: those within
// sqrt(2) spacings, since (1 - sqrt(3)/3)^3 is 0.255 of (1 - 1/3)^3), and leaves the rest off.
TEST(AggregationMultigrid, LumpingWeakCouplingsKeepsTheRowSums) {
  const Matrix a = wide_stencil_laplacian(10);
  const Matrix lumped = lump_weak_couplings(a, 0.3);
  const Eigen::VectorXd ones = Eigen::VectorXd::Ones(a.cols());
  const Eigen::VectorXd sums = a * ones;
  const Eigen::VectorXd lumped_sums = lumped * ones;
  EXPECT_LE((sums - lumped_sums).lpNorm<Eigen::Infinity>(), 1e-12 * a.diagonal().maxCoeff());
  const auto inner = static_cast<Eigen::Index>((5 * 10 + 5) * 10 + 5);
  EXPECT_EQ(a.row(inner).nonZeros(), 93);
  EXPECT_EQ(lumped.row(inner).nonZeros(), 19);
  const double kept_weights =
      6.0 * std::pow(1.0 - 1.0 / 3.0, 3) + 12.0 * std::pow(1.0 - std::sqrt(2.0) / 3.0, 3);
  EXPECT_NEAR(lumped.coeff(inner, inner), kept_weights, 1e-12);
}

// The multigrid lumping the finest operator's weak couplings, as the SPH solve asks, solves the
// wide stencil's equation as conjugate gradient does, in under a third of Jacobi's iterations
// (measured 2026-11-28: 6 against 25).
TEST(AggregationMultigrid, SolvesTheWideStencilOfTheSphLaplacian) {
  multigrid_iterations(wide_stencil_laplacian(20), "wide stencil 20^3", 0.3);
}

// The 5-point Laplacian of an n x n square with p = 0 above its top side, whose middle half is
// a pocket joined to the rest only through faces open by `open` (a grid fluid's cells behind a
// partly blocked face), with a source inside the pocket.
std::pair<Matrix, Eigen::VectorXd> pocket_laplacian(int n, double open) {
  auto inside = [n](int i, int j) {
    return i >= n / 4 && i < 3 * n / 4 && j >= n / 4 && j < 3 * n / 4;
  };
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::VectorXd b = Eigen::VectorXd::Zero(n * n);
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const int row = j * n + i;
      double diagonal = j == n - 1 ? 2.0 : 0.0;
      const int neighbours[4][2] = {{i - 1, j}, {i + 1, j}, {i, j - 1}, {i, j + 1}};
      for (const auto& c : neighbours) {
        if (c[0] < 0 || c[0] >= n || c[1] < 0 || c[1] >= n)
          continue;
        const double w = inside(i, j) == inside(c[0], c[1]) ? 1.0 : open;
        diagonal += w;
        entries.emplace_back(row, c[1] * n + c[0], -w);
      }
      entries.emplace_back(row, row, diagonal);
      b[row] = inside(i, j) ? 1.0 : 0.0;
    }
  }
  Matrix a(n * n, n * n);
  a.setFromTriplets(entries.begin(), entries.end());
  return {a, b};
}

// Regression (2026-11-30): the truck drum's two-phase pressure on 5 mm cells took 603 BiCGSTAB
// iterations with the weak couplings lumped, and 17 without. Lumped, the faces into the pocket
// (0.2 of the others in both rows) vanish from the V-cycle's operator, which leaves the pocket
// floating, while they carry all of its source. Unlumped (the default), the iterations stay
// those of a plain square; lumped, they grow with the grid (measured: 128^2 18 against 128;
// 32^2 12 against 42). Bounds: 25 unlumped, and lumped above twice that, so that the test
// shows what lumping did.
TEST(AggregationMultigrid, SolvesThroughPartlyBlockedFacesWithoutLumping) {
  const auto [a, b] = pocket_laplacian(128, 0.2);
  Eigen::VectorXd x;
  const int plain = multigrid_iterations_to_solve(a, b, x, 0.0);
  const int lumped = multigrid_iterations_to_solve(a, b, x, 0.3);
  std::printf("pocket 128^2: %d iterations, lumped %d\n", plain, lumped);
  EXPECT_LE(plain, 25);
  EXPECT_GT(lumped, 2 * 25);
}

}  // namespace
}  // namespace partimix
