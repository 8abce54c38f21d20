// The Verlet list holds each pair within the radius once, in increasing partner index, split at
// `split`, through periodic images; it serves until a particle has moved half the skin and finds
// the same pairs as brute force at every use.
#include <gtest/gtest.h>

#include <random>
#include <tuple>
#include <vector>

#include "particles/neighbour_list.hpp"
#include "random_points.hpp"

namespace partimix {
namespace {

constexpr double kRadius = 0.1;
constexpr double kSkin = 0.02;

// (i, j, j >= split) in the order the list visits them.
using Visits = std::vector<std::tuple<std::size_t, std::size_t, bool>>;

Visits brute_force(const Domain& domain, const std::vector<Vec3>& x, std::size_t count,
                   std::size_t split) {
  Visits visits;
  for (std::size_t i = 0; i < count; ++i) {
    for (const bool beyond : {false, true}) {
      for (std::size_t j = i + 1; j < x.size(); ++j) {
        if ((j >= split) == beyond && domain.displacement(x[i], x[j]).norm() < kRadius)
          visits.emplace_back(i, j, beyond);
      }
    }
  }
  return visits;
}

Visits from_list(const NeighbourList& list, const Domain& domain, const std::vector<Vec3>& x,
                 std::size_t count) {
  Visits visits;
  for (std::size_t i = 0; i < count; ++i) {
    auto record = [&](bool beyond) {
      return [&, beyond](std::size_t j, const Vec3& rij, double r2) {
        EXPECT_NEAR((rij - domain.displacement(x[i], x[j])).norm(), 0.0, 1e-12);
        EXPECT_NEAR(r2, rij.squaredNorm(), 1e-15);
        visits.emplace_back(i, j, beyond);
      };
    };
    list.for_each_partner(i, x, record(false), record(true));
  }
  return visits;
}

Domain box(int dimensions, bool periodic) {
  Domain domain;
  domain.dimensions = dimensions;
  domain.hi = dimensions == 3 ? Vec3(1.0, 0.8, 0.6) : Vec3(1.0, 0.8, 0.0);
  domain.periodic = {periodic, periodic, false};
  return domain;
}

void expect_brute_force(int dimensions, bool periodic, unsigned seed) {
  const Domain domain = box(dimensions, periodic);
  const auto x = random_points(domain, 800, seed);
  NeighbourList list(domain, kRadius, kSkin);
  list.update(x, 500, 300);
  EXPECT_EQ(from_list(list, domain, x, 500), brute_force(domain, x, 500, 300));
}

TEST(NeighbourList, MatchesBruteForce2D) {
  expect_brute_force(2, false, 1);
}
TEST(NeighbourList, MatchesBruteForce3D) {
  expect_brute_force(3, false, 2);
}
TEST(NeighbourList, MatchesBruteForcePeriodic2D) {
  expect_brute_force(2, true, 3);
}
TEST(NeighbourList, MatchesBruteForcePeriodic3D) {
  expect_brute_force(3, true, 4);
}

// Every particle moves by just under half the skin in a random direction: the list is kept
// and still finds every pair; one more step past half the skin rebuilds it.
TEST(NeighbourList, ServesUntilAParticleHasMovedHalfTheSkin) {
  const Domain domain = box(3, false);
  auto x = random_points(domain, 800, 5);
  NeighbourList list(domain, kRadius, kSkin);
  list.update(x, x.size(), x.size());
  std::mt19937_64 rng(6);
  std::normal_distribution<double> normal;
  std::vector<Vec3> direction(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    direction[i] = Vec3(normal(rng), normal(rng), normal(rng)).normalized();
    x[i] += 0.499 * kSkin * direction[i];
  }
  list.update(x, x.size(), x.size());
  EXPECT_EQ(list.builds(), 1u);
  EXPECT_EQ(from_list(list, domain, x, x.size()), brute_force(domain, x, x.size(), x.size()));
  x[17] += 0.002 * kSkin * direction[17];
  list.update(x, x.size(), x.size());
  EXPECT_EQ(list.builds(), 2u);
}

TEST(NeighbourList, RebuildsWhenInvalidatedOrTheLayoutChanges) {
  const Domain domain = box(3, false);
  const auto x = random_points(domain, 400, 7);
  NeighbourList list(domain, kRadius, kSkin);
  list.update(x, 200, 200);
  list.update(x, 200, 200);
  EXPECT_EQ(list.builds(), 1u);
  list.invalidate();
  list.update(x, 200, 200);
  EXPECT_EQ(list.builds(), 2u);
  list.update(x, 200, 300);
  EXPECT_EQ(list.builds(), 3u);
}

}  // namespace
}  // namespace partimix
