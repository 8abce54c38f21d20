// coupling/kernel_weights.hpp and coupling/void_fraction.hpp (docs/cfd-dem.md, "Void fraction:
// the grains' volume on the grid"): the grains' volume on the grid equals theirs to round-off,
// in the open, against blocked cells, across a periodic side and with cells smaller than a
// grain; the void fraction changes smoothly as a grain moves; grains in no open cell are
// counted, and clipping is counted.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "cfd/flow_mask.hpp"
#include "coupling/kernel_weights.hpp"
#include "coupling/void_fraction.hpp"
#include "grid/staggered_grid.hpp"
#include "support/uniform_random.hpp"

namespace partimix::coupling {
namespace {

using grid::StaggeredGrid;

double grains_on_grid(const StaggeredGrid& grid, const std::vector<double>& eps) {
  double sum = 0.0;
  for (const double e : eps)
    sum += (1.0 - e) * grid.cell_volume();
  return sum;
}

// Random grains of diameter d in [lo, hi)^3.
void scatter(std::size_t count, double d, const Vec3& lo, const Vec3& hi, unsigned seed,
             std::vector<Vec3>& positions, std::vector<double>& volumes) {
  test_support::Uniform random(seed);
  for (std::size_t n = 0; n < count; ++n) {
    positions.emplace_back(lo.x() + (hi.x() - lo.x()) * random(),
                           lo.y() + (hi.y() - lo.y()) * random(),
                           lo.z() + (hi.z() - lo.z()) * random());
    volumes.push_back(M_PI * d * d * d / 6.0);
  }
}

// 10 x 8 x 6 cells of 1 cm, periodic along x.
StaggeredGrid periodic_box() {
  return StaggeredGrid(3, Vec3::Zero(), {10, 8, 6}, Vec3(0.01, 0.01, 0.01), {true, false, false},
                       1e6);
}

// The open cells of `grid` but its floor row (y = 0), which is solid.
cfd::FlowMask floor_blocked(const StaggeredGrid& grid) {
  cfd::FlowMask mask = cfd::open_mask(grid);
  for (int i = 0; i < grid.cells(0); ++i)
    for (int k = 0; k < grid.cells(2); ++k)
      mask.open_cell[grid.cell(i, 0, k)] = 0;
  cfd::open_faces(grid, mask);
  return mask;
}

// Grains everywhere in a box with a blocked slab and a periodic axis: the volume is kept, and
// nothing lands on the blocked cells.
TEST(VoidFraction, KeepsTheGrainsVolumeAgainstWallsAndAcrossAPeriodicSide) {
  const StaggeredGrid grid = periodic_box();
  const cfd::FlowMask mask = floor_blocked(grid);
  std::vector<Vec3> positions;
  std::vector<double> volumes;
  scatter(300, 0.004, Vec3(0.0, 0.01, 0.0), Vec3(0.1, 0.08, 0.06), 1, positions, volumes);
  KernelWeights weights;
  weights.build(grid, mask, positions, 0.008);  // two diameters
  EXPECT_EQ(weights.unmapped(), 0u);
  std::vector<double> eps;
  EXPECT_EQ(void_fraction(grid, weights, volumes, 0.0, eps), 0u);
  double total = 0.0;
  for (const double v : volumes)
    total += v;
  EXPECT_NEAR(grains_on_grid(grid, eps), total, 1e-12 * total);
  for (int i = 0; i < 10; ++i)
    for (int k = 0; k < 6; ++k)
      EXPECT_EQ(eps[grid.cell(i, 0, k)], 1.0);
  // A grain by the periodic side shares its volume with the cells across it.
  KernelWeights one;
  one.build(grid, mask, std::vector<Vec3>{Vec3(0.0005, 0.045, 0.035)}, 0.008);
  bool across = false;
  for (const KernelWeights::Weight& w : one.of(0))
    across = across || grid.cell_coordinates(w.cell)[0] == 9;
  EXPECT_TRUE(across);
}

// Cells a quarter of a grain wide, a packing of about 0.55: the void fraction stays within
// [0.2, 1] without clipping (the cell holding a grain's centre would be full many times over
// with the grain's whole volume in it).
TEST(VoidFraction, StaysWellBehavedWithCellsSmallerThanAGrain) {
  const double d = 0.004;
  const StaggeredGrid grid(3, Vec3::Zero(), {24, 24, 24}, Vec3::Constant(d / 4.0), {}, 1e7);
  const cfd::FlowMask mask = cfd::open_mask(grid);
  std::vector<Vec3> positions;
  std::vector<double> volumes;
  // A simple cubic packing of spacing d * 0.98 in the middle of the box: 0.55 solid.
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) {
        positions.emplace_back(
            Vec3(0.008 + 0.98 * d * i, 0.008 + 0.98 * d * j, 0.008 + 0.98 * d * k));
        volumes.push_back(M_PI * d * d * d / 6.0);
      }
  KernelWeights weights;
  weights.build(grid, mask, positions, 2.0 * d);
  std::vector<double> eps;
  EXPECT_EQ(void_fraction(grid, weights, volumes, 0.0, eps), 0u);
  double lowest = 1.0;
  for (const double e : eps)
    lowest = std::min(lowest, e);
  std::printf("lowest void fraction with cells of d/4: %.3f\n", lowest);
  EXPECT_GT(lowest, 0.2);
  EXPECT_NEAR(grains_on_grid(grid, eps), 27.0 * volumes[0], 1e-12 * 27.0 * volumes[0]);
}

// A grain moving h/20 at a time across a cell face: no cell's void fraction changes by more
// than a tenth of V_i / V_c in a step (the cell-centred mapping would jump by all of it). The
// weights are Lipschitz: max |W'| = 2.11 at q = 1/4, so a move of h/20 with b = 2h changes a
// cell's unnormalised weight by at most 2.11 / 40 = 0.053, and the normaliser is above 1.
TEST(VoidFraction, ChangesSmoothlyAsAGrainCrossesACellFace) {
  const double h = 0.01;
  const StaggeredGrid grid(2, Vec3::Zero(), {8, 8, 1}, Vec3(h, h, 1.0), {}, 1e6);
  const cfd::FlowMask mask = cfd::open_mask(grid);
  const std::vector<double> volume{1e-5};
  KernelWeights weights;
  std::vector<double> before;
  std::vector<double> after;
  double largest = 0.0;
  for (int step = 0; step <= 40; ++step) {
    weights.build(grid, mask, std::vector<Vec3>{Vec3(0.035 + step * h / 20.0, 0.041, 0.0)},
                  2.0 * h);
    void_fraction(grid, weights, volume, 0.0, after);
    if (step > 0)
      for (std::size_t c = 0; c < after.size(); ++c)
        largest = std::max(largest, std::abs(after[c] - before[c]));
    before = after;
  }
  const double full = volume[0] / grid.cell_volume();
  std::printf("largest change of a cell's void fraction per h/20: %.4f of V_i / V_c\n",
              largest / full);
  EXPECT_LT(largest, 0.1 * full);
}

TEST(VoidFraction, CountsGrainsInNoOpenCellAndClippedCells) {
  const StaggeredGrid grid(2, Vec3::Zero(), {4, 4, 1}, Vec3(0.01, 0.01, 1.0), {}, 1e6);
  cfd::FlowMask mask = cfd::open_mask(grid);
  mask.open_cell[grid.cell(0, 0, 0)] = 0;
  cfd::open_faces(grid, mask);
  KernelWeights weights;
  // Outside the box, inside a blocked cell with a support too small to reach an open one, NaN,
  // and one grain too large for its cell.
  weights.build(grid, mask,
                std::vector<Vec3>{Vec3(-1.0, 0.02, 0.0), Vec3(0.005, 0.005, 0.0),
                                  Vec3(std::nan(""), 0.0, 0.0), Vec3(0.021, 0.021, 0.0)},
                0.004);
  EXPECT_EQ(weights.unmapped(), 3u);
  EXPECT_EQ(weights.of(3).size(), 1u);  // no cell centre within 4 mm: the holding cell
  std::vector<double> eps;
  const std::vector<double> volumes{1.0, 1.0, 1.0, 2e-4};
  EXPECT_EQ(void_fraction(grid, weights, volumes, 0.3, eps), 1u);
  EXPECT_EQ(eps[grid.cell(2, 2, 0)], 0.3);
}

// The divided mapping: the volume kept against the blocked floor row and across the periodic
// side, a grain inside one cell all in it, one astride a face shared by its sub-cubes.
TEST(VoidFraction, DividedMappingKeepsTheVolumeAndSharesByParts) {
  const StaggeredGrid grid = periodic_box();
  const cfd::FlowMask mask = floor_blocked(grid);
  std::vector<Vec3> positions;
  std::vector<double> volumes;
  scatter(300, 0.004, Vec3(0.0, 0.01, 0.0), Vec3(0.1, 0.08, 0.06), 1, positions, volumes);
  const std::vector<double> radii(positions.size(), 0.002);
  KernelWeights weights;
  weights.build_divided(grid, mask, positions, radii);
  EXPECT_EQ(weights.unmapped(), 0u);
  std::vector<double> eps;
  void_fraction(grid, weights, volumes, 0.0, eps);
  double total = 0.0;
  for (const double v : volumes)
    total += v;
  EXPECT_NEAR(grains_on_grid(grid, eps), total, 1e-12 * total);
  KernelWeights inside;
  inside.build_divided(grid, mask, std::vector<Vec3>{Vec3(0.045, 0.045, 0.035)},
                       std::vector<double>{0.002});
  ASSERT_EQ(inside.of(0).size(), 1u);
  EXPECT_EQ(inside.of(0)[0].weight, 1.0);
  // Centred 1 mm below the face x = 0.05: of the 81 sub-cubes inside the sphere (21 in each of the
  // three middle layers along x, 9 in each outer one) the outer layer at +1.6 mm lies above it.
  KernelWeights astride;
  astride.build_divided(grid, mask, std::vector<Vec3>{Vec3(0.049, 0.045, 0.035)},
                        std::vector<double>{0.002});
  ASSERT_EQ(astride.of(0).size(), 2u);
  double above = 0.0;
  for (const KernelWeights::Weight& w : astride.of(0))
    if (grid.cell_coordinates(w.cell)[0] == 5)
      above = w.weight;
  EXPECT_DOUBLE_EQ(above, 9.0 / 81.0);
}

}  // namespace
}  // namespace partimix::coupling
