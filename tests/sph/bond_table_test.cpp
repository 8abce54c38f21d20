// The bonds of total Lagrangian solids and the cracks that cut them (docs/multi-material-sph.md,
// "Total Lagrangian solids"): on a square lattice bonded to 3 spacings, failing the particles of
// one column cuts exactly their bonds and the bonds that cross the column, leaves the others
// intact, and gives the same cuts whatever order the column fails in.
#include "sph/multi_material/bond_table.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "particles/cell_grid.hpp"
#include "support/multi_material_setup.hpp"

namespace partimix::sph {
namespace {

constexpr int kSide = 9;
constexpr int kColumn = 4;
constexpr double kSupport = 2.0;
constexpr double kH = 1.5;  // bonds reach kSupport * kH = 3 spacings

struct Lattice {
  std::vector<Vec3> reference;
  std::vector<double> h;
  std::vector<std::uint8_t> flagged;
  BondTable bonds;

  Lattice() {
    for (int j = 0; j < kSide; ++j)
      for (int i = 0; i < kSide; ++i)
        reference.emplace_back(i, j, 0.0);
    h.assign(reference.size(), kH);
    flagged.assign(reference.size(), 1);
    CellGrid grid(test_support::plane_domain(-1.0, -1.0, kSide, kSide), kSupport * kH);
    grid.build(reference);
    bonds.build(grid, reference, h, flagged, kSupport);
  }
  int column(std::size_t i) const { return static_cast<int>(reference[i].x()); }
  // The column's particles, bottom to top.
  std::vector<std::size_t> column_particles() const {
    std::vector<std::size_t> particles;
    for (std::size_t i = 0; i < reference.size(); ++i) {
      if (column(i) == kColumn)
        particles.push_back(i);
    }
    return particles;
  }
  // What a bond between i and j should be once the column has failed.
  Bond expected(std::size_t i, std::size_t j) const {
    if (i == j || (reference[i] - reference[j]).norm() >= kSupport * kH)
      return Bond::none;
    const bool on_column = column(i) == kColumn || column(j) == kColumn;
    const bool across = (column(i) - kColumn) * (column(j) - kColumn) < 0;
    return on_column || across ? Bond::cut : Bond::intact;
  }
  void fail(const std::vector<std::size_t>& order) {
    for (const std::size_t k : order)
      bonds.fail(k, reference, 0.5);
  }
};

TEST(BondTable, FailedColumnCutsExactlyTheBondsThatCrossIt) {
  Lattice lattice;
  lattice.fail(lattice.column_particles());
  const std::size_t n = lattice.reference.size();
  for (std::size_t i = 0; i < n; ++i) {
    EXPECT_EQ(lattice.bonds.failed(i), lattice.column(i) == kColumn) << i;
    for (std::size_t j = 0; j < n; ++j) {
      EXPECT_EQ(lattice.bonds.state(i, j), lattice.expected(i, j)) << i << " " << j;
    }
  }
}

TEST(BondTable, CutsDoNotDependOnTheOrderOfFailure) {
  Lattice upward;
  Lattice downward;
  std::vector<std::size_t> order = upward.column_particles();
  upward.fail(order);
  std::reverse(order.begin(), order.end());
  downward.fail(order);
  const std::size_t n = upward.reference.size();
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < n; ++j)
      EXPECT_EQ(upward.bonds.state(i, j), downward.bonds.state(i, j)) << i << " " << j;
  }
}

TEST(BondTable, ForEachIntactVisitsTheIntactBondsAlone) {
  Lattice lattice;
  lattice.fail(lattice.column_particles());
  for (std::size_t i = 0; i < lattice.reference.size(); ++i) {
    lattice.bonds.for_each_intact(i, [&](std::size_t j) {
      EXPECT_EQ(lattice.expected(i, j), Bond::intact) << i << " " << j;
    });
  }
}

}  // namespace
}  // namespace partimix::sph
