// cfd/pressure_projection.hpp (docs/cfd.md, "One time step"): after the projection the discrete
// continuity equation holds in every open cell to the solver's tolerance, whatever the void
// fraction, coefficients and sources; a discrete gradient is removed entirely (the projection is
// the discrete Helmholtz split); a field that already satisfies continuity is left alone; and
// regions cut off from each other each keep their own balance.
#include <gtest/gtest.h>

#include "cfd/continuity_residual.hpp"
#include "cfd/flow_mask.hpp"
#include "cfd/pressure_projection.hpp"
#include "grid/staggered_grid.hpp"
#include "support/uniform_random.hpp"

namespace partimix::cfd {
namespace {

using grid::StaggeredGrid;

constexpr double kTolerance = 1e-10;

// Random values in [lo, hi) on the open faces, 0 on the others.
FaceArrays random_on_open_faces(const StaggeredGrid& grid, const FlowMask& mask, double lo,
                                double hi, unsigned seed) {
  test_support::Uniform random(seed);
  FaceArrays arrays = face_arrays(grid, 0.0);
  for (int axis = 0; axis < 3; ++axis)
    for (std::size_t f = 0; f < arrays[axis].size(); ++f)
      arrays[axis][f] = mask.open_face[axis][f] ? lo + (hi - lo) * random() : 0.0;
  return arrays;
}

double largest(const FaceArrays& arrays) {
  double m = 0.0;
  for (const std::vector<double>& a : arrays)
    for (const double v : a)
      m = std::max(m, std::abs(v));
  return m;
}

TEST(PressureProjection, MakesARandomFieldSatisfyContinuityInAClosedBox) {
  const StaggeredGrid grid(3, Vec3::Zero(), {6, 5, 4}, Vec3(0.1, 0.12, 0.09), {}, 1e6);
  const FlowMask mask = open_mask(grid);
  FaceArrays velocity = random_on_open_faces(grid, mask, -1.0, 1.0, 1);
  const FaceArrays void_fraction = face_arrays(grid, 1.0);
  const FaceArrays coefficient = face_arrays(grid, 0.01);
  const std::vector<double> source(grid.cell_count(), 0.0);
  ASSERT_GT(continuity_residual(grid, mask, void_fraction, velocity, source), 1.0);
  PressureProjection projection(kTolerance, 200);
  projection.lay_out(grid, mask);
  std::vector<double> correction;
  const LinearSolve result =
      projection.project(grid, mask, void_fraction, coefficient, source, velocity, correction);
  EXPECT_TRUE(result.converged);
  EXPECT_LT(continuity_residual(grid, mask, void_fraction, velocity, source), 1e-8);
  EXPECT_LT(projection.imbalance(), 1e-12);
}

// Void fraction and coefficients varying from face to face, a periodic axis, and a source
// s = Δε/Δt of zero sum.
TEST(PressureProjection, HoldsWithVaryingVoidFractionSourcesAndAPeriodicAxis) {
  const StaggeredGrid grid(2, Vec3::Zero(), {8, 6, 1}, Vec3(0.05, 0.04, 1.0), {true, false, false},
                           1e6);
  const FlowMask mask = open_mask(grid);
  FaceArrays velocity = random_on_open_faces(grid, mask, -0.5, 0.5, 2);
  FaceArrays void_fraction = random_on_open_faces(grid, mask, 0.4, 1.0, 3);
  for (int axis = 0; axis < 2; ++axis)
    for (std::size_t f = 0; f < void_fraction[axis].size(); ++f)
      if (!mask.open_face[axis][f])
        void_fraction[axis][f] = 0.7;
  const FaceArrays coefficient = random_on_open_faces(grid, mask, 1e-3, 3e-3, 4);
  std::vector<double> source(grid.cell_count());
  test_support::Uniform random(5);
  double sum = 0.0;
  for (double& s : source) {
    s = -2.0 + 4.0 * random();
    sum += s;
  }
  for (double& s : source)
    s -= sum / static_cast<double>(source.size());
  PressureProjection projection(kTolerance, 200);
  projection.lay_out(grid, mask);
  std::vector<double> correction;
  EXPECT_TRUE(
      projection.project(grid, mask, void_fraction, coefficient, source, velocity, correction)
          .converged);
  EXPECT_LT(continuity_residual(grid, mask, void_fraction, velocity, source), 1e-8);
}

// u* = a ∇q on the open faces of a box with fixed walls: the projection takes it all away and
// its correction is q up to a constant.
TEST(PressureProjection, RemovesADiscreteGradientEntirely) {
  const StaggeredGrid grid(3, Vec3::Zero(), {5, 4, 3}, Vec3(0.1, 0.1, 0.1), {}, 1e6);
  const FlowMask mask = open_mask(grid);
  std::vector<double> q(grid.cell_count());
  for (std::size_t c = 0; c < q.size(); ++c)
    q[c] = std::sin(0.7 * static_cast<double>(c)) + 0.01 * static_cast<double>(c);
  const double a = 0.02;
  FaceArrays velocity = face_arrays(grid, 0.0);
  for (int axis = 0; axis < 3; ++axis)
    for (int k = 0; k < grid.faces(axis, 2); ++k)
      for (int j = 0; j < grid.faces(axis, 1); ++j)
        for (int i = 0; i < grid.faces(axis, 0); ++i) {
          const std::size_t f = grid.face(axis, i, j, k);
          if (!mask.open_face[axis][f])
            continue;
          std::array<int, 3> below{i, j, k};
          below[axis] -= 1;
          velocity[axis][f] =
              a * (q[grid.cell(i, j, k)] - q[grid.cell(below[0], below[1], below[2])]) / 0.1;
        }
  PressureProjection projection(1e-12, 200);
  projection.lay_out(grid, mask);
  std::vector<double> correction;
  projection.project(grid, mask, face_arrays(grid, 1.0), face_arrays(grid, a),
                     std::vector<double>(grid.cell_count(), 0.0), velocity, correction);
  EXPECT_LT(largest(velocity), 1e-9);
  for (std::size_t c = 0; c < q.size(); ++c)
    EXPECT_NEAR(correction[c] - correction[0], q[c] - q[0], 1e-8);
}

// A stream function's discrete curl satisfies continuity exactly: nothing to correct.
TEST(PressureProjection, LeavesAFieldThatSatisfiesContinuityAlone) {
  const StaggeredGrid grid(2, Vec3::Zero(), {7, 5, 1}, Vec3(0.2, 0.1, 1.0), {}, 1e6);
  const FlowMask mask = open_mask(grid);
  // psi at the cell corners (nodes), zero on the box's sides.
  auto psi = [](int i, int j) {
    return (i == 0 || j == 0 || i == 7 || j == 5) ? 0.0 : std::cos(1.3 * i + 0.4 * j) + 2.0;
  };
  FaceArrays velocity = face_arrays(grid, 0.0);
  for (int j = 0; j < 5; ++j)
    for (int i = 0; i <= 7; ++i)
      velocity[0][grid.face(0, i, j, 0)] = (psi(i, j + 1) - psi(i, j)) / 0.1;
  for (int j = 0; j <= 5; ++j)
    for (int i = 0; i < 7; ++i)
      velocity[1][grid.face(1, i, j, 0)] = -(psi(i + 1, j) - psi(i, j)) / 0.2;
  const FaceArrays before = velocity;
  PressureProjection projection(kTolerance, 200);
  projection.lay_out(grid, mask);
  std::vector<double> correction;
  projection.project(grid, mask, face_arrays(grid, 1.0), face_arrays(grid, 0.01),
                     std::vector<double>(grid.cell_count(), 0.0), velocity, correction);
  for (int axis = 0; axis < 2; ++axis)
    for (std::size_t f = 0; f < velocity[axis].size(); ++f)
      EXPECT_NEAR(velocity[axis][f], before[axis][f], 1e-12);
}

// A wall of blocked cells across the box leaves two regions, each with its own pressure level
// and each brought to continuity.
TEST(PressureProjection, BalancesRegionsCutOffFromEachOther) {
  const StaggeredGrid grid(2, Vec3::Zero(), {9, 6, 1}, Vec3(0.1, 0.1, 1.0), {}, 1e6);
  FlowMask mask = open_mask(grid);
  for (int j = 0; j < 6; ++j)
    mask.open_cell[grid.cell(4, j, 0)] = 0;
  open_faces(grid, mask);
  FaceArrays velocity = random_on_open_faces(grid, mask, -1.0, 1.0, 6);
  PressureProjection projection(kTolerance, 200);
  projection.lay_out(grid, mask);
  std::vector<double> correction;
  const std::vector<double> source(grid.cell_count(), 0.0);
  EXPECT_TRUE(projection
                  .project(grid, mask, face_arrays(grid, 1.0), face_arrays(grid, 0.01), source,
                           velocity, correction)
                  .converged);
  EXPECT_LT(continuity_residual(grid, mask, face_arrays(grid, 1.0), velocity, source), 1e-8);
  EXPECT_EQ(correction[grid.cell(0, 0, 0)], 0.0);  // each region's first cell is held
  EXPECT_EQ(correction[grid.cell(5, 0, 0)], 0.0);
}

// A source whose sum is not zero in a closed box cannot be met; the imbalance is reported and
// spread evenly.
TEST(PressureProjection, ReportsTheImbalanceOfSourcesAClosedBoxCannotMeet) {
  const StaggeredGrid grid(2, Vec3::Zero(), {4, 4, 1}, Vec3(0.1, 0.1, 1.0), {}, 1e6);
  const FlowMask mask = open_mask(grid);
  FaceArrays velocity = face_arrays(grid, 0.0);
  std::vector<double> source(grid.cell_count(), 0.0);
  source[5] = 1.6;  // mean 0.1 per cell
  PressureProjection projection(kTolerance, 200);
  projection.lay_out(grid, mask);
  std::vector<double> correction;
  projection.project(grid, mask, face_arrays(grid, 1.0), face_arrays(grid, 0.01), source, velocity,
                     correction);
  EXPECT_NEAR(projection.imbalance(), 0.1, 1e-12);
  EXPECT_NEAR(continuity_residual(grid, mask, face_arrays(grid, 1.0), velocity, source), 0.1, 1e-8);
}

}  // namespace
}  // namespace partimix::cfd
