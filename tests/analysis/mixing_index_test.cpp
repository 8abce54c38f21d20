// Mixing measures (docs/mixing.md): the uniformity index xi of eq. (S28) and the Lacey index M
// on hand-counted cells, on fully segregated halves, on a checkerboard that puts the same number
// of tracers in every cell, and on random mixtures, where E[n N0 xi] = 1 and E[S^2] = Sr^2.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <stdexcept>
#include <vector>

#include "analysis/mixing_index.hpp"
#include "support/uniform_random.hpp"

namespace partimix::analysis {
namespace {

using test_support::Uniform;

constexpr double kPi = std::numbers::pi;

struct Sample {
  std::vector<Vec3> positions;
  std::vector<MixingRole> roles;
  void add(const Vec3& x, bool tracer) {
    positions.push_back(x);
    roles.push_back(tracer ? MixingRole::tracer : MixingRole::other);
  }
};

// The seed's set-up: a cylinder along z about the origin, as in its 69.3 mm sampling cylinder.
struct Cylinder {
  CylinderRegion region;
  int n_r = 4;
  int n_theta = 8;
  int n_z = 4;
  CylinderCells cells() const { return CylinderCells(region, n_r, n_theta, n_z); }
  int count() const { return n_r * n_theta * n_z; }
};

Cylinder seed_cylinder() {
  Cylinder c;
  c.region.radius = 0.0693;
  c.region.z0 = 0.0;
  c.region.z1 = 0.15;
  return c;
}

// m_r x m_theta x m_z points in every cell, on a grid uniform in (r^2, theta, z) inside the
// cell, so each cell holds exactly m = m_r m_theta m_z particles. `tracer(x, parity)` picks the
// tracers; parity is that of the sub-grid index sum, a checkerboard inside each cell.
template <class IsTracer>
Sample per_cell_grid(const Cylinder& c, int m_r, int m_theta, int m_z, IsTracer tracer) {
  Sample s;
  const double r2 = c.region.radius * c.region.radius;
  const double height = c.region.z1 - c.region.z0;
  for (int layer = 0; layer < c.n_z; ++layer)
    for (int sector = 0; sector < c.n_theta; ++sector)
      for (int ring = 0; ring < c.n_r; ++ring)
        for (int a = 0; a < m_r; ++a)
          for (int b = 0; b < m_theta; ++b)
            for (int k = 0; k < m_z; ++k) {
              const double r = std::sqrt(r2 * (ring + (a + 0.5) / m_r) / c.n_r);
              const double theta = 2.0 * kPi * (sector + (b + 0.5) / m_theta) / c.n_theta;
              const double z = c.region.z0 + height * (layer + (k + 0.5) / m_z) / c.n_z;
              const Vec3 x(r * std::cos(theta), r * std::sin(theta), z);
              s.add(x, tracer(x, (a + b + k) % 2 == 1));
            }
  return s;
}

// n points uniform in the cylinder (rejection from the bounding box), each a tracer with
// probability 1/2 independently of where it is.
Sample random_mixture(const Cylinder& c, int n, Uniform& uniform) {
  Sample s;
  const double radius = c.region.radius;
  while (static_cast<int>(s.positions.size()) < n) {
    const double x = radius * (2.0 * uniform() - 1.0);
    const double y = radius * (2.0 * uniform() - 1.0);
    const double z = c.region.z0 + (c.region.z1 - c.region.z0) * uniform();
    const bool tracer = uniform() < 0.5;
    if (x * x + y * y < radius * radius)
      s.add(Vec3(x, y, z), tracer);
  }
  return s;
}

// Counts set by hand on a row of cells.
CellCounts hand_counts(const std::vector<std::int64_t>& tracer,
                       const std::vector<std::int64_t>& total) {
  const int n = static_cast<int>(tracer.size());
  CellCounts counts(BoxCells(Vec3::Zero(), Vec3(n, 1.0, 1.0), {n, 1, 1}));
  counts.tracer = tracer;
  counts.total = total;
  return counts;
}

TEST(CountCells, CountsTracersAndAllParticlesIgnoringWallsAndOutsiders) {
  const BoxCells cells(Vec3::Zero(), Vec3(2.0, 1.0, 1.0), {2, 1, 1});
  const std::vector<Vec3> x = {Vec3(0.5, 0.5, 0.5), Vec3(0.6, 0.5, 0.5), Vec3(1.5, 0.5, 0.5),
                               Vec3(1.5, 0.5, 0.5), Vec3(5.0, 0.5, 0.5)};
  const std::vector<MixingRole> roles = {MixingRole::tracer, MixingRole::other, MixingRole::ignored,
                                         MixingRole::tracer, MixingRole::tracer};
  CellCounts counts(cells);
  counts.tracer = {7, 7};  // stale values from an earlier sample are overwritten
  count_cells(cells, x, roles, counts);
  EXPECT_EQ(counts.tracer, (std::vector<std::int64_t>{1, 1}));
  EXPECT_EQ(counts.total, (std::vector<std::int64_t>{2, 1}));
}

TEST(CountCells, RejectsMismatchedInputs) {
  const BoxCells two(Vec3::Zero(), Vec3::Ones(), {2, 1, 1});
  const BoxCells three(Vec3::Zero(), Vec3::Ones(), {3, 1, 1});
  CellCounts counts(two);
  const std::vector<Vec3> x = {Vec3(0.5, 0.5, 0.5)};
  const std::vector<MixingRole> roles = {MixingRole::tracer};
  EXPECT_THROW(count_cells(three, x, roles, counts), std::invalid_argument);
  EXPECT_THROW(count_cells(two, x, std::span<const MixingRole>(), counts), std::invalid_argument);
}

// Four cells, N = {3, 1, 0, 0}: N0 = 4, Nbar = 1, sum (N_i - Nbar)^2 = 4 + 0 + 1 + 1 = 6,
// xi = 6 / (3 * 16) = 1/8. All four in one cell: sum = 9 + 1 + 1 + 1 = 12, xi = 1/4 = 1/n.
TEST(UniformityIndex, MatchesHandCountedCells) {
  EXPECT_DOUBLE_EQ(uniformity_index(hand_counts({3, 1, 0, 0}, {3, 1, 0, 0})), 0.125);
  EXPECT_DOUBLE_EQ(uniformity_index(hand_counts({0, 4, 0, 0}, {9, 9, 9, 9})), 0.25);
  EXPECT_DOUBLE_EQ(uniformity_index(hand_counts({2, 2, 2, 2}, {5, 2, 9, 3})), 0.0);
}

TEST(UniformityIndex, IsNaNWithoutTracersOrWithOneCell) {
  EXPECT_TRUE(std::isnan(uniformity_index(hand_counts({0, 0, 0}, {3, 1, 2}))));
  EXPECT_TRUE(std::isnan(uniformity_index(hand_counts({4}, {4}))));
}

// Cells {5/10, 2/10, 2/2} with min_count 5: the last cell is left out, so p = 7/20,
// phi = {1/2, 1/5}, S^2 = (0.15^2 + 0.15^2) / 1 = 0.045, S0^2 = 0.35 * 0.65 = 0.2275,
// nbar = 10, Sr^2 = 0.02275 and M = (0.2275 - 0.045) / (0.2275 - 0.02275).
TEST(LaceyIndex, MatchesHandCountedCellsAndSkipsSparseCells) {
  const CellCounts counts = hand_counts({5, 2, 2}, {10, 10, 2});
  const LaceyResult m = lacey_index(counts, 5);
  ASSERT_EQ(m.status, LaceyStatus::ok);
  EXPECT_EQ(m.cells, 2);
  EXPECT_DOUBLE_EQ(m.tracer_fraction, 0.35);
  EXPECT_DOUBLE_EQ(m.mean_count, 10.0);
  EXPECT_NEAR(m.variance, 0.045, 1e-15);
  EXPECT_NEAR(m.segregated_variance, 0.2275, 1e-15);
  EXPECT_NEAR(m.random_variance, 0.02275, 1e-15);
  EXPECT_NEAR(m.index, (0.2275 - 0.045) / (0.2275 - 0.02275), 1e-14);
  EXPECT_EQ(lacey_index(counts, 1).cells, 3);
  EXPECT_EQ(lacey_index(hand_counts({0, 1, 1}, {0, 2, 2}), 0).cells, 2);
}

TEST(LaceyIndex, DegenerateCasesAreNaNWithTheirReason) {
  const auto status_and_nan = [](const CellCounts& counts, int min_count) {
    const LaceyResult m = lacey_index(counts, min_count);
    EXPECT_TRUE(std::isnan(m.index));
    return m.status;
  };
  EXPECT_EQ(status_and_nan(hand_counts({0, 0, 0}, {4, 5, 6}), 1), LaceyStatus::no_tracer);
  EXPECT_EQ(status_and_nan(hand_counts({4, 5, 6}, {4, 5, 6}), 1), LaceyStatus::no_other);
  EXPECT_EQ(status_and_nan(hand_counts({1, 0, 0}, {9, 0, 0}), 1), LaceyStatus::too_few_cells);
  EXPECT_EQ(status_and_nan(hand_counts({1, 1, 1}, {9, 9, 2}), 10), LaceyStatus::too_few_cells);
  EXPECT_EQ(status_and_nan(hand_counts({1, 0, 1}, {1, 1, 1}), 1),
            LaceyStatus::one_particle_per_cell);
}

// Tracers are the particles with y < 0 (the seed's red half). With n_theta even, the sectors
// split at the x-z plane, so n/2 cells hold m tracers and n/2 hold none; every cell holds m
// particles. By hand: Nbar = m/2, sum_i (N_i - Nbar)^2 = n m^2 / 4 and N0 = n m / 2, so
// xi = 1 / (n (n - 1)). For Lacey: p = 1/2, S0^2 = 1/4, phi_i in {0, 1} half each, so
// S^2 = (n/4) / (n - 1) and Sr^2 = 1/(4m), giving M = -m / ((n - 1)(m - 1)): not exactly 0,
// because S^2 is the (n - 1)-divisor sample variance while S0^2 = p (1 - p) is a population
// variance. |M| <= m / ((n - 1)(m - 1)) is the tolerance on "M = 0"; it vanishes as n grows.
TEST(MixingIndices, FullySegregatedHalves) {
  const Cylinder c = seed_cylinder();
  const int m_r = 4, m_theta = 3, m_z = 2, m = m_r * m_theta * m_z;
  const Sample s =
      per_cell_grid(c, m_r, m_theta, m_z, [](const Vec3& x, bool) { return x.y() < 0.0; });
  const CylinderCells cells = c.cells();
  CellCounts scratch(cells);
  const double n = c.count();
  const double xi = uniformity_index(cells, s.positions, s.roles, scratch);
  EXPECT_NEAR(xi * n * (n - 1.0), 1.0, 1e-12);
  const LaceyResult lacey = lacey_index(cells, s.positions, s.roles, 1, scratch);
  ASSERT_EQ(lacey.status, LaceyStatus::ok);
  const double bound = m / ((n - 1.0) * (m - 1.0));
  EXPECT_NEAR(lacey.index, -bound, 1e-12);
  EXPECT_LE(std::abs(lacey.index), bound + 1e-15);
}

// Tracers on a checkerboard inside every cell: each of the m = 24 grid points per cell
// alternates, so every cell holds exactly m/2 tracers. Then N_i = Nbar (xi = 0 to round-off)
// and S^2 = 0, so M = S0^2 / (S0^2 - Sr^2) = nbar / (nbar - 1): an ordered mixture beats a
// random one, and M -> 1 only in the limit of many particles per cell, |M - 1| = 1/(nbar - 1).
TEST(MixingIndices, CheckerboardInEveryCylinderCell) {
  const Cylinder c = seed_cylinder();
  const int m = 4 * 3 * 2;
  const Sample s = per_cell_grid(c, 4, 3, 2, [](const Vec3&, bool odd) { return odd; });
  const CylinderCells cells = c.cells();
  CellCounts scratch(cells);
  EXPECT_EQ(uniformity_index(cells, s.positions, s.roles, scratch), 0.0);
  const LaceyResult lacey = lacey_index(cells, s.positions, s.roles, 1, scratch);
  ASSERT_EQ(lacey.status, LaceyStatus::ok);
  EXPECT_EQ(lacey.variance, 0.0);
  EXPECT_NEAR(lacey.index, m / (m - 1.0), 1e-14);
}

// The same on a box (a DEM drum's bins): a 24^3 lattice, tracers where i + j + k is odd,
// 4 x 4 x 4 cells of 6^3 = 216 points, 108 of them tracers. M = 216/215, within 1/215 of 1.
TEST(MixingIndices, CheckerboardLatticeInBoxCells) {
  const int side = 24;
  const BoxCells cells(Vec3::Zero(), Vec3::Ones(), {4, 4, 4});
  Sample s;
  for (int k = 0; k < side; ++k)
    for (int j = 0; j < side; ++j)
      for (int i = 0; i < side; ++i)
        s.add((Vec3(i, j, k) + Vec3::Constant(0.5)) / side, (i + j + k) % 2 == 1);
  CellCounts scratch(cells);
  EXPECT_EQ(uniformity_index(cells, s.positions, s.roles, scratch), 0.0);
  const LaceyResult lacey = lacey_index(cells, s.positions, s.roles, 1, scratch);
  const double nbar = 216.0;
  EXPECT_EQ(lacey.mean_count, nbar);
  EXPECT_NEAR(lacey.index, nbar / (nbar - 1.0), 1e-14);
  EXPECT_LE(lacey.index - 1.0, 1.0 / (nbar - 1.0) + 1e-14);
}

// Random mixture statistics (docs/mixing.md), n = 128 equal-volume cells, nbar = 100:
// - xi: given N0, the tracer counts are multinomial with p = 1/n, so sum (N_i - Nbar)^2 / Nbar
//   is Pearson's chi^2 with n - 1 degrees of freedom: n N0 xi = chi^2 / (n - 1) has mean
//   exactly 1 and standard deviation sqrt(2 / (n - 1)) = 0.125.
// - M: given the cell totals n_i, the cell fractions are independent with variance
//   p (1 - p) / n_i, so E[S^2] = p (1 - p) E[1/n_i] = Sr^2 (1 + 1/nbar + ...): E[M] = 1 - b with
//   b = 1 / (nbar (nbar - 1)) = 1e-4, allowed as 2 b. S^2 scatters like a sample variance of
//   n values, sd(S^2) = Sr^2 sqrt(2 / (n - 1)), so sd(M) = sqrt(2 / (n - 1)) / (nbar - 1)
//   = 1.3e-3.
struct RandomMixtureStatistics {
  int cells = 0;
  double nbar = 0.0;
  double xi_sd() const { return std::sqrt(2.0 / (cells - 1)); }
  double lacey_bias() const { return 2.0 / (nbar * (nbar - 1.0)); }
  double lacey_sd() const { return std::sqrt(2.0 / (cells - 1)) / (nbar - 1.0); }
};

// One realisation (fixed seed), held to five standard deviations.
TEST(MixingIndices, RandomMixtureHasXiNearOneOverNN0AndLaceyNearOne) {
  const Cylinder c = seed_cylinder();
  const RandomMixtureStatistics stats{c.count(), 100.0};
  Uniform uniform(1954);
  const Sample s = random_mixture(c, c.count() * 100, uniform);
  const CylinderCells cells = c.cells();
  CellCounts scratch(cells);
  const double xi = uniformity_index(cells, s.positions, s.roles, scratch);
  std::int64_t n0 = 0;
  for (const std::int64_t count : scratch.tracer)
    n0 += count;
  EXPECT_NEAR(xi * c.count() * static_cast<double>(n0), 1.0, 5.0 * stats.xi_sd());
  const LaceyResult lacey = lacey_index(cells, s.positions, s.roles, 1, scratch);
  ASSERT_EQ(lacey.status, LaceyStatus::ok);
  EXPECT_EQ(lacey.cells, c.count());
  EXPECT_NEAR(lacey.index, 1.0, stats.lacey_bias() + 5.0 * stats.lacey_sd());
}

// The mean over 100 realisations tests the expectations themselves, to five standard errors
// (sd / 10): 5 * 0.125 / 10 = 0.063 for n N0 xi, and 5 * 1.3e-3 / 10 + 2e-4 = 8.4e-4 for M
// (bias allowance included).
TEST(MixingIndices, RandomMixtureExpectationsHoldOverManyRealisations) {
  const Cylinder c = seed_cylinder();
  const RandomMixtureStatistics stats{c.count(), 100.0};
  const CylinderCells cells = c.cells();
  CellCounts scratch(cells);
  Uniform uniform(257);
  const int realisations = 100;
  double xi_sum = 0.0, lacey_sum = 0.0;
  for (int k = 0; k < realisations; ++k) {
    const Sample s = random_mixture(c, c.count() * 100, uniform);
    const double xi = uniformity_index(cells, s.positions, s.roles, scratch);
    std::int64_t n0 = 0;
    for (const std::int64_t count : scratch.tracer)
      n0 += count;
    xi_sum += xi * c.count() * static_cast<double>(n0);
    lacey_sum += lacey_index(scratch, 1).index;
  }
  const double root = std::sqrt(static_cast<double>(realisations));
  EXPECT_NEAR(xi_sum / realisations, 1.0, 5.0 * stats.xi_sd() / root);
  EXPECT_NEAR(lacey_sum / realisations, 1.0, stats.lacey_bias() + 5.0 * stats.lacey_sd() / root);
}

}  // namespace
}  // namespace partimix::analysis
