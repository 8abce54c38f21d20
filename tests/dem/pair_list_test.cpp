// The DEM's half neighbour list with a skin (docs/dem.md, "The solver"): it lists exactly the
// pairs within R_i + R_j + skin (against all pairs), goes stale only when a grain has moved half
// the skin, carries the springs of touching pairs through a re-sort (sign changed and the
// superquadric warm start dropped when a pair's order flips), and delivers each grain's loads
// in the order of its partners, the same to the last bit for any number of blocks.
#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <set>
#include <utility>

#include <gtest/gtest.h>

#include "dem/pair_list.hpp"

namespace partimix::dem {
namespace {

struct Bed {
  Domain domain;
  std::vector<Vec3> x;
  std::vector<double> radius;
};

// 400 grains of radii 1-2 mm at random in a 4 cm box periodic along x.
Bed random_bed() {
  Bed bed;
  bed.domain.lo = Vec3::Zero();
  bed.domain.hi = Vec3::Constant(0.04);
  bed.domain.periodic = {true, false, false};
  std::mt19937 random(7);
  std::uniform_real_distribution<double> along(0.0, 0.04);
  std::uniform_real_distribution<double> size(0.001, 0.002);
  for (int k = 0; k < 400; ++k) {
    bed.x.emplace_back(along(random), along(random), along(random));
    bed.radius.push_back(size(random));
  }
  return bed;
}

constexpr double kSkin = 0.001;

// The list of `bed`, built on a grid of cells 2 R_max + skin wide.
struct Listed {
  explicit Listed(const Bed& bed) : grid(bed.domain, 2 * 0.002 + kSkin) {
    grid.build(bed.x);
    list.build(grid, bed.x, bed.radius);
  }
  CellGrid grid;
  PairList list{kSkin};
};

std::set<std::pair<std::uint32_t, std::uint32_t>> listed(const PairList& list) {
  std::set<std::pair<std::uint32_t, std::uint32_t>> pairs;
  for (std::size_t k = 0; k < list.size(); ++k)
    pairs.emplace(list.first(k), list.second(k));
  return pairs;
}

TEST(PairList, ListsExactlyThePairsWithinTheSumOfRadiiAndTheSkin) {
  const Bed bed = random_bed();
  Listed listed_bed(bed);
  PairList& list = listed_bed.list;
  std::set<std::pair<std::uint32_t, std::uint32_t>> expected;
  for (std::uint32_t i = 0; i < bed.x.size(); ++i) {
    for (std::uint32_t j = i + 1; j < bed.x.size(); ++j) {
      const double reach = bed.radius[i] + bed.radius[j] + kSkin;
      if (bed.domain.displacement(bed.x[i], bed.x[j]).norm() < reach)
        expected.emplace(i, j);
    }
  }
  ASSERT_GT(expected.size(), 100u);
  EXPECT_EQ(listed(list), expected);
  for (std::size_t k = 1; k < list.size(); ++k) {  // by first grain, then second
    EXPECT_TRUE(std::make_pair(list.first(k - 1), list.second(k - 1)) <
                std::make_pair(list.first(k), list.second(k)));
  }
}

TEST(PairList, GoesStaleWhenAGrainHasMovedHalfTheSkin) {
  Bed bed = random_bed();
  bed.x[3].x() = bed.domain.hi.x() - 0.0001;
  EXPECT_TRUE(PairList(kSkin).stale(bed.x, bed.domain));
  Listed listed_bed(bed);
  const PairList& list = listed_bed.list;
  EXPECT_FALSE(list.stale(bed.x, bed.domain));
  bed.x[17].y() += 0.49 * kSkin;
  EXPECT_FALSE(list.stale(bed.x, bed.domain));
  bed.x[17].y() += 0.02 * kSkin;
  EXPECT_TRUE(list.stale(bed.x, bed.domain));
  bed.x[17].y() -= 0.51 * kSkin;
  // Across the periodic boundary and wrapped: 0.3 mm through the nearest image.
  bed.x[3].x() = bed.domain.lo.x() + 0.0002;
  EXPECT_FALSE(list.stale(bed.x, bed.domain));
}

TEST(PairList, SpringsFollowTheirGrainsThroughAReSortAndFlipWithThePair) {
  Bed bed = random_bed();
  Listed listed_bed(bed);
  PairList& list = listed_bed.list;
  ASSERT_GT(list.size(), 10u);
  const std::uint32_t a = list.first(5);
  const std::uint32_t b = list.second(5);
  list.history(5).spring = Vec3(1, 2, 3);
  list.history(5).rolling_spring = Vec3(4, 5, 6);
  list.history(5).midway = Vec3f(1e-4F, 0, 0);
  list.history(5).mu = 0.9F;
  list.partition(1);
  std::vector<Vec3> force(bed.x.size(), Vec3::Zero());
  std::vector<Vec3> torque(bed.x.size(), Vec3::Zero());
  list.deliver(5, PairLoad{}, force, torque);
  // Rebuilt in place: the whole history stays, the midway point included.
  list.build(listed_bed.grid, bed.x, bed.radius);
  EXPECT_EQ(list.history(5).midway, Vec3f(1e-4F, 0, 0));
  EXPECT_EQ(list.history(5).mu, 0.9F);
  list.history(6).spring = Vec3(7, 8, 9);  // not touching: not carried
  // Reverse the grains: new grain k is old grain n - 1 - k, so every pair's order flips.
  const std::size_t n = bed.x.size();
  std::vector<std::uint32_t> new_to_old(n);
  std::iota(new_to_old.rbegin(), new_to_old.rend(), 0u);
  std::vector<Vec3> reversed(n);
  std::vector<double> reversed_radius(n);
  for (std::size_t k = 0; k < n; ++k) {
    reversed[k] = bed.x[new_to_old[k]];
    reversed_radius[k] = bed.radius[new_to_old[k]];
  }
  listed_bed.grid.build(reversed);
  list.build(listed_bed.grid, reversed, reversed_radius, new_to_old);
  int carried = 0;
  for (std::size_t k = 0; k < list.size(); ++k) {
    if (list.first(k) == n - 1 - b && list.second(k) == n - 1 - a) {
      EXPECT_EQ(list.history(k).spring, Vec3(-1, -2, -3));
      EXPECT_EQ(list.history(k).rolling_spring, Vec3(-4, -5, -6));
      EXPECT_EQ(list.history(k).mu, 0.0F);  // kept from the other grain's centre: dropped
      EXPECT_TRUE(list.touching(k));
      ++carried;
    } else {
      EXPECT_EQ(list.history(k).spring, Vec3::Zero());
      EXPECT_FALSE(list.touching(k));
    }
  }
  EXPECT_EQ(carried, 1);
}

// Loads of pair k spread over 12 orders of magnitude, so that a sum in another order differs in
// its last bits.
PairLoad load_of_pair(std::size_t k) {
  const double size =
      std::pow(10.0, static_cast<double>(k % 13) - 6.0) * (1.0 + 1e-3 * static_cast<double>(k));
  return {Vec3(size, 2.0 / size, 3.0), Vec3(0.0, size / 3.0, 1.0), Vec3(0.1, 0.0, size / 7.0)};
}

struct Loads {
  std::vector<Vec3> force;
  std::vector<Vec3> torque;
};

// The loads of the touching pairs (two in three) delivered block by block, then gathered.
Loads delivered(PairList& list, std::size_t grains, int blocks, int& gathered) {
  Loads loads{std::vector<Vec3>(grains, Vec3::Constant(9.0)),
              std::vector<Vec3>(grains, Vec3::Constant(9.0))};
  list.partition(blocks);
  for (int b = 0; b < list.blocks(); ++b) {
    const std::uint32_t begin = list.block_start(b);
    const std::uint32_t end = list.block_start(b + 1);
    std::fill(loads.force.begin() + begin, loads.force.begin() + end, Vec3::Zero());
    std::fill(loads.torque.begin() + begin, loads.torque.begin() + end, Vec3::Zero());
    for (std::size_t k = list.pair_start(begin); k < list.pair_start(end); ++k) {
      if (k % 3 == 0)
        list.set_apart(k);
      else
        list.deliver(k, load_of_pair(k), loads.force, loads.torque);
    }
  }
  gathered = 0;
  for (std::size_t i = 0; i < grains; ++i) {
    if (list.gathered(i)) {
      list.gather(i, loads.force[i], loads.torque[i]);
      ++gathered;
    }
  }
  return loads;
}

TEST(PairList, DeliversEachGrainsLoadsInPartnerOrderWhateverTheBlocks) {
  const Bed bed = random_bed();
  Listed listed_bed(bed);
  PairList& list = listed_bed.list;
  const std::size_t n = bed.x.size();
  Loads serial{std::vector<Vec3>(n, Vec3::Zero()), std::vector<Vec3>(n, Vec3::Zero())};
  for (std::size_t k = 0; k < list.size(); ++k) {  // in pair order: partners in index order
    if (k % 3 == 0)
      continue;
    const PairLoad load = load_of_pair(k);
    serial.force[list.first(k)] += load.force;
    serial.force[list.second(k)] -= load.force;
    serial.torque[list.first(k)] += load.torque_i;
    serial.torque[list.second(k)] += load.torque_j;
  }
  for (const int blocks : {1, 2, 3, 7}) {
    int gathered = 0;
    const Loads loads = delivered(list, n, blocks, gathered);
    EXPECT_EQ(list.blocks(), blocks);
    if (blocks == 1)
      EXPECT_EQ(gathered, 0);
    else
      EXPECT_GT(gathered, 0) << blocks;
    EXPECT_LT(gathered, static_cast<int>(n) / 2) << blocks;
    for (std::size_t i = 0; i < n; ++i) {
      ASSERT_EQ(loads.force[i], serial.force[i]) << blocks << " blocks, grain " << i;
      ASSERT_EQ(loads.torque[i], serial.torque[i]) << blocks << " blocks, grain " << i;
    }
  }
  int touching_pairs = 0;
  for (std::size_t i = 0; i < n; ++i)
    touching_pairs += list.contacts(i);
  EXPECT_EQ(touching_pairs, 2 * static_cast<int>(list.size() - (list.size() + 2) / 3));
}

TEST(PairList, BlocksShareThePairsEvenly) {
  const Bed bed = random_bed();
  Listed listed_bed(bed);
  PairList& list = listed_bed.list;
  list.partition(4);
  ASSERT_EQ(list.blocks(), 4);
  EXPECT_EQ(list.block_start(0), 0u);
  EXPECT_EQ(list.block_start(4), bed.x.size());
  for (int b = 0; b < 4; ++b) {
    const double pairs =
        list.pair_start(list.block_start(b + 1)) - list.pair_start(list.block_start(b));
    const double all = static_cast<double>(list.size());
    EXPECT_NEAR(pairs, all / 4.0, 0.05 * all) << b;
  }
  list.partition(1000);  // more blocks than grains: one grain each
  EXPECT_EQ(list.blocks(), static_cast<int>(bed.x.size()));
}

}  // namespace
}  // namespace partimix::dem
