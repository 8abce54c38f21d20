// The transpose viscous term (cfd/transpose_viscous.hpp; docs/cfd.md, "One time step") against
// a field where it is known: a periodic unit square, u = (0, sin 2πx) (divergence-free),
// η = 1 + sin(2πy) / 2, ε = 1, where T = Σ_b ∂_b (η ∂_a u_b) = (2π² cos 2πx cos 2πy, 0). Asserted
// (set before the runs): the largest error on 32 x 32 cells within 1% of the peak 2π², falling
// 3.8-4.2 times when the cells halve (second order); and zero to round-off for a constant η with
// any divergence-free field.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "cfd/transpose_viscous.hpp"
#include "grid/staggered_grid.hpp"

namespace partimix::cfd {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

grid::StaggeredGrid square(int n) {
  const double h = 1.0 / n;
  return grid::StaggeredGrid(2, Vec3::Zero(), {n, n, 1}, Vec3(h, h, 1.0), {true, true, false}, 1e6);
}

// The largest |T_x - exact| over the x faces, and the largest |T_y|.
std::pair<double, double> errors(int n) {
  const grid::StaggeredGrid grid = square(n);
  const FlowMask mask = open_mask(grid);
  FaceArrays velocity = face_arrays(grid, 0.0);
  grid.for_each_face(1, [&](const std::array<int, 3>& f, std::size_t index) {
    velocity[1][index] = std::sin(kTwoPi * grid.face_centre(1, f[0], f[1], f[2]).x());
  });
  std::vector<double> eps(grid.cell_count(), 1.0);
  std::vector<double> eta(grid.cell_count(), 0.0);
  grid.for_each_cell([&](const std::array<int, 3>& c, std::size_t index) {
    eta[index] = 1.0 + 0.5 * std::sin(kTwoPi * grid.cell_centre(c[0], c[1], c[2]).y());
  });
  FaceArrays out = face_arrays(grid, 0.0);
  transpose_viscous_term(grid, mask, eps, eta, velocity, out);
  double ex = 0.0;
  grid.for_each_face(0, [&](const std::array<int, 3>& f, std::size_t index) {
    const Vec3 x = grid.face_centre(0, f[0], f[1], f[2]);
    const double exact =
        0.5 * kTwoPi * kTwoPi * std::cos(kTwoPi * x.x()) * std::cos(kTwoPi * x.y());
    ex = std::max(ex, std::abs(out[0][index] - exact));
  });
  double ey = 0.0;
  for (const double t : out[1])
    ey = std::max(ey, std::abs(t));
  return {ex, ey};
}

TEST(TransposeViscous, MatchesTheKnownFieldToSecondOrder) {
  const double peak = 0.5 * kTwoPi * kTwoPi;
  const auto [coarse, coarse_y] = errors(32);
  const auto [fine, fine_y] = errors(64);
  std::printf(
      "transpose term: largest error %.3e (32 cells), %.3e (64), of the peak %.3f; "
      "ratio %.2f; T_y up to %.1e\n",
      coarse / peak, fine / peak, peak, coarse / fine, coarse_y);
  EXPECT_LT(coarse, 0.01 * peak);
  EXPECT_GT(coarse / fine, 3.8);
  EXPECT_LT(coarse / fine, 4.2);
  EXPECT_LT(coarse_y, 1e-12);
  EXPECT_LT(fine_y, 1e-12);
}

TEST(TransposeViscous, VanishesForAConstantViscosityAndADivergenceFreeField) {
  const grid::StaggeredGrid grid = square(16);
  const FlowMask mask = open_mask(grid);
  FaceArrays velocity = face_arrays(grid, 0.0);
  // u = curl of ψ = sin 2πx sin 4πy, discretely divergence-free from the nodes' ψ.
  const auto psi = [](double x, double y) {
    return std::sin(kTwoPi * x) * std::sin(2.0 * kTwoPi * y);
  };
  const double h = 1.0 / 16;
  grid.for_each_face(0, [&](const std::array<int, 3>& f, std::size_t index) {
    const double x = f[0] * h;
    velocity[0][index] = (psi(x, (f[1] + 1) * h) - psi(x, f[1] * h)) / h;
  });
  grid.for_each_face(1, [&](const std::array<int, 3>& f, std::size_t index) {
    const double y = f[1] * h;
    velocity[1][index] = -(psi((f[0] + 1) * h, y) - psi(f[0] * h, y)) / h;
  });
  const std::vector<double> eps(grid.cell_count(), 0.6);
  const std::vector<double> eta(grid.cell_count(), 2.5);
  FaceArrays out = face_arrays(grid, 0.0);
  transpose_viscous_term(grid, mask, eps, eta, velocity, out);
  for (int a = 0; a < 2; ++a)
    for (const double t : out[a])
      EXPECT_NEAR(t, 0.0, 1e-9);
}

}  // namespace
}  // namespace partimix::cfd
