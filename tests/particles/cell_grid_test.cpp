// Neighbour search equals brute force on random sets (2D, 3D, periodic).
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <random>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "particles/cell_grid.hpp"
#include "random_points.hpp"

namespace partimix {
namespace {

using Pairs = std::vector<std::pair<std::size_t, std::size_t>>;

Pairs brute_force(const Domain& domain, const std::vector<Vec3>& x, double radius) {
  Pairs pairs;
  for (std::size_t i = 0; i < x.size(); ++i) {
    for (std::size_t j = 0; j < x.size(); ++j) {
      if (domain.displacement(x[i], x[j]).norm() < radius)
        pairs.emplace_back(i, j);
    }
  }
  return pairs;
}

Pairs from_grid(const Domain& domain, const std::vector<Vec3>& x, double radius) {
  CellGrid grid(domain, radius);
  grid.build(x);
  Pairs pairs;
  for (std::size_t i = 0; i < x.size(); ++i) {
    grid.for_each_neighbour(i, x, [&](std::size_t j, const Vec3& rij, double r2) {
      EXPECT_NEAR((rij - domain.displacement(x[i], x[j])).norm(), 0.0, 1e-12);
      EXPECT_NEAR(r2, rij.squaredNorm(), 1e-15);
      pairs.emplace_back(i, j);
    });
  }
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

void expect_same_as_brute_force(const Domain& domain, double radius, unsigned seed) {
  const auto x = random_points(domain, 600, seed);
  EXPECT_EQ(from_grid(domain, x, radius), brute_force(domain, x, radius));
}

TEST(CellGrid, MatchesBruteForce2D) {
  Domain domain;
  domain.dimensions = 2;
  domain.lo = Vec3(-1.0, 0.0, 0.0);
  domain.hi = Vec3(1.0, 1.5, 0.0);
  expect_same_as_brute_force(domain, 0.13, 1);
}

TEST(CellGrid, MatchesBruteForce3D) {
  Domain domain;
  domain.hi = Vec3(1.0, 0.7, 0.5);
  expect_same_as_brute_force(domain, 0.11, 2);
}

TEST(CellGrid, MatchesBruteForcePeriodic2D) {
  Domain domain;
  domain.dimensions = 2;
  domain.hi = Vec3(1.0, 1.0, 0.0);
  domain.periodic = {true, true, false};
  expect_same_as_brute_force(domain, 0.15, 3);
}

TEST(CellGrid, MatchesBruteForcePeriodic3D) {
  Domain domain;
  domain.hi = Vec3(0.6, 0.8, 1.0);
  domain.periodic = {true, false, true};
  expect_same_as_brute_force(domain, 0.17, 4);
}

// With index bounds the search returns exactly the pairs with j in [above, below).
TEST(CellGrid, IndexBoundsKeepExactlyTheIndicesBetweenThem) {
  Domain domain;
  domain.hi = Vec3(1.0, 0.7, 0.5);
  domain.periodic = {true, false, false};
  const auto x = random_points(domain, 600, 6);
  CellGrid grid(domain, 0.12);
  grid.build(x);
  for (const auto& [above, below] :
       {std::pair<std::size_t, std::size_t>{0, 250}, {120, 600}, {120, 250}}) {
    Pairs found;
    for (std::size_t i = 0; i < x.size(); ++i) {
      grid.for_each_neighbour(
          i, x, [&](std::size_t j, const Vec3&, double) { found.emplace_back(i, j); }, below,
          above);
    }
    std::sort(found.begin(), found.end());
    Pairs expected;
    for (const auto& pair : brute_force(domain, x, 0.12)) {
      if (pair.second >= above && pair.second < below)
        expected.push_back(pair);
    }
    ASSERT_GT(expected.size(), 100u);
    EXPECT_EQ(found, expected) << above << " to " << below;
  }
}

TEST(CellGrid, RejectsPeriodicAxisShorterThanThreeCellsNamingTheMinimum) {
  Domain domain;
  domain.periodic = {true, false, false};
  try {
    CellGrid(domain, 0.4);
    FAIL() << "a periodic axis of 2.5 radii was accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(error.location().key_path, "domain.periodic");
    EXPECT_NE(error.message().find("3 x 0.4 m = 1.2 m"), std::string::npos) << error.message();
  }
}

// A domain of 1e6 radii per axis would need 1e18 cells of one radius: the cells grow instead,
// and the neighbours found are still every pair within the radius.
TEST(CellGrid, AHugeDomainGetsBoundedWiderCells) {
  Domain domain;
  domain.hi = Vec3(1e5, 1e5, 1e5);
  const CellGrid grid(domain, 0.1);
  const auto& cells = grid.cells_per_axis();
  EXPECT_LE(static_cast<double>(cells[0]) * cells[1] * cells[2], double(1 << 24));
  const std::vector<Vec3> x{Vec3(5.0, 5.0, 5.0), Vec3(5.05, 5.0, 5.0), Vec3(9e4, 9e4, 9e4)};
  EXPECT_EQ(from_grid(domain, x, 0.1), (Pairs{{0, 0}, {0, 1}, {1, 0}, {1, 1}, {2, 2}}));
}

// A few fine grains in a large domain (1 mm grains in a truck drum): radius / 2 cells would be
// 2^24, over which every build passes three times; the cells are bounded by the particle count
// instead (16 per particle, the count rounded up to a power of two, at least 4096), laid out
// again as the count grows, and the
// neighbours found stay every pair within the radius (against brute force).
TEST(CellGrid, FewParticlesInALargeDomainGetCellsBoundedByTheirCount) {
  Domain domain;
  const double radius = 0.002;
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Vec3> x;
  for (int i = 0; i < 3000; ++i) {
    const Vec3 p(unit(random), unit(random), unit(random));
    x.push_back(p);
    if (i % 3 == 0)  // close neighbours, so that there are pairs to find
      x.push_back(p + Vec3(0.001, 0.0005, 0.0));
  }
  CellGrid grid(domain, radius);
  for (const std::size_t n : {std::size_t{100}, x.size()}) {
    const std::vector<Vec3> some(x.begin(), x.begin() + static_cast<std::ptrdiff_t>(n));
    grid.build(some);
    const auto& cells = grid.cells_per_axis();
    const double count = static_cast<double>(cells[0]) * cells[1] * cells[2];
    EXPECT_LE(count, std::max(4096.0, 16.0 * static_cast<double>(std::bit_ceil(n)))) << n;
    Pairs pairs;
    for (std::size_t i = 0; i < some.size(); ++i)
      grid.for_each_neighbour(
          i, some, [&](std::size_t j, const Vec3&, double) { pairs.emplace_back(i, j); });
    std::sort(pairs.begin(), pairs.end());
    EXPECT_EQ(pairs, brute_force(domain, some, radius)) << n;
  }
}

TEST(CellGrid, NonFinitePositionsGoToAnEdgeCell) {
  Domain domain;
  CellGrid grid(domain, 0.2);
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<Vec3> x{Vec3(inf, -inf, 0.5), Vec3(std::nan(""), 0.5, 0.5), Vec3(0.5, 0.5, 0.5)};
  grid.build(x);
  EXPECT_EQ(grid.cell_order().size(), 3u);
}

TEST(CellGrid, CellOrderIsAPermutation) {
  Domain domain;
  const auto x = random_points(domain, 200, 5);
  CellGrid grid(domain, 0.2);
  grid.build(x);
  std::vector<std::uint32_t> order(grid.cell_order().begin(), grid.cell_order().end());
  std::sort(order.begin(), order.end());
  for (std::uint32_t k = 0; k < order.size(); ++k)
    EXPECT_EQ(order[k], k);
}

}  // namespace
}  // namespace partimix
