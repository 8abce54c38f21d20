// Planar granular column collapse with MPM (seed 003, section 3.1; docs/mpm.md; docs/validation.md,
// "MPM column collapse"): a column of the seed's ceramic beads, L_i wide and H_i high, against a
// slip wall (the symmetry plane), on a rough floor, released at t = 0. Reported: the runout
// L_f (the largest x reached by the material, taken as the x below which 99.5% of the mass lies,
// so that a single stray point does not set it) and the final height H_f.
// Neither the reduced stiffness nor the time step matters: doubling E (each run at its own
// stable step) changes the runout by less than 2% (docs/mpm.md, "Reduced stiffness"), and a
// third of the step by less than 2% (docs/mpm.md, "Transfers": the filter is a rate, so the
// numerical dissipation does not grow with the number of steps). 2% is about what the runout
// resolves here: a point spacing (2.5 mm) is 1.9% of L_f - L_i.
// Against the aspect ratio: short columns keep their top (asserted). The runout of tall columns
// against the published a^(2/3) law is a documented study (docs/validation.md, "MPM column
// collapse"), not asserted here: with 6 to 10 cells across the column the exponent between
// a = 3 and 6 is 0.95 to 0.75 (not converged), and finer grids cost minutes per column.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "support/mpm_setups.hpp"

namespace partimix::mpm {
namespace {

using test_support::box_fill;
using test_support::domain_2d;
using test_support::mpm_config;
using test_support::plane_wall;
using test_support::seed_beads;

constexpr double kWidth = 0.06;  // L_i
constexpr double kCell = 0.01;

struct Deposit {
  double runout = 0.0;  // L_f [m]
  double height = 0.0;  // H_f [m]
  double width = 0.0;   // L_i [m]
};

// The deposit of a column `width` wide (L_i) at `end`, stepped at dt (0: the solver's stable
// step).
Deposit collapse(double aspect_ratio, double youngs_modulus, double end, double dt = 0.0,
                 double width = kWidth) {
  MpmConfig config = mpm_config(kCell, seed_beads(youngs_modulus));
  config.fills = {box_fill(Vec3(0, 0, -1), Vec3(width, aspect_ratio * width, 1), kCell / 2)};
  config.walls = {plane_wall(Vec3::Zero(), Vec3::UnitY(), GridBoundary::no_slip),
                  plane_wall(Vec3::Zero(), Vec3::UnitX(), GridBoundary::slip)};
  ParticleStore store;
  MpmSolver solver(store,
                   domain_2d(Vec3::Zero(), Vec3((3.0 + 1.5 * aspect_ratio) * width,
                                                (aspect_ratio + 0.3) * width, 0)),
                   config, Vec3(0, -9.81, 0), {});
  if (dt > 0.0) {
    while (solver.time() < end)
      solver.step(dt);
  } else {
    test_support::run_mpm(solver, end);
  }
  std::vector<double> x;
  Deposit deposit;
  deposit.width = width;
  for (const Vec3& position : store.position()) {
    x.push_back(position.x());
    deposit.height = std::max(deposit.height, position.y());
  }
  std::sort(x.begin(), x.end());
  const double half = 0.25 * kCell;  // a point's half-spacing: the material's edge
  deposit.runout = x[static_cast<std::size_t>(0.995 * static_cast<double>(x.size() - 1))] + half;
  deposit.height += half;
  return deposit;
}

// The change of the runout L_f - L_i between two deposits, relative to the first.
double runout_change(const Deposit& first, const Deposit& second) {
  return std::abs(second.runout - first.runout) / (first.runout - first.width);
}

TEST(MpmCollapse, DoublingTheReducedStiffnessChangesTheRunoutByLessThanTwoPercent) {
  const Deposit soft = collapse(1.8, 1.0e7, 0.6);
  const Deposit stiff = collapse(1.8, 2.0e7, 0.6);
  EXPECT_LT(runout_change(soft, stiff), 0.02);
  RecordProperty("runout_soft", std::to_string(soft.runout));
  RecordProperty("runout_stiff", std::to_string(stiff.runout));
  RecordProperty("height_soft", std::to_string(soft.height));
  RecordProperty("height_stiff", std::to_string(stiff.height));
}

// With APIC filtered every step the runout fell by 7% from cfl 0.3 to 0.2, and on without end
// ((L_f - L_i) / L_i = 2.11, 1.98, 1.73, 1.51 at cfl 0.3, 0.2, 0.1, 0.05, 10 cm column).
// Measured now: 0.7% (this column; 1.1% before the averaged dilation), 0.1% (the 10 cm column, cfl
// 0.3 against 0.1).
TEST(MpmCollapse, AThirdOfTheTimeStepChangesTheRunoutByLessThanTwoPercent) {
  const double stable = 0.3 * kCell / seed_beads(1.0e7).wave_speed();
  const Deposit coarse = collapse(1.8, 1.0e7, 0.6, stable);
  const Deposit fine = collapse(1.8, 1.0e7, 0.6, stable / 3.0);
  EXPECT_LT(runout_change(coarse, fine), 0.02);
  RecordProperty("runout_cfl_03", std::to_string(coarse.runout));
  RecordProperty("runout_cfl_01", std::to_string(fine.runout));
}

// The normalised runout (L_f - L_i) / L_i.
double normalised_runout(const Deposit& deposit) {
  return (deposit.runout - deposit.width) / deposit.width;
}

// Short columns keep their top: only a wedge at the foot slides (H_f = H_i below a of about
// 0.7-1; Lube et al. 2005, Lajeunesse et al. 2005; docs/validation.md, "MPM column collapse").
TEST(MpmCollapse, AShortColumnKeepsItsTop) {
  const double a = 0.5;
  const Deposit deposit = collapse(a, 1.0e7, 0.5);
  EXPECT_NEAR(deposit.height / (a * kWidth), 1.0, 0.02);
  RecordProperty("height_over_initial", std::to_string(deposit.height / (a * kWidth)));
  RecordProperty("runout", std::to_string(normalised_runout(deposit)));
}

// Tall columns: the runout grows as a power of a. Balmforth & Kerswell 2005 (J. Fluid Mech. 538,
// 399, abstract) measured (L_f - L_i) / L_i ~ a^(0.9 +- 0.1) in wide channels, which plane
// strain (no side walls) stands for, against a^(0.65 +- 0.05) in narrow slots, whose side walls
// add friction (Lube et al. 2005's a^(2/3) is of that kind); the constant depends on the
// material. The exponent between a = 3 and a = 6 is asserted within their 0.9 +- 0.1, for a
// column 10 cells wide: 0.88 (runouts 4.52 and 8.31). On 6 cells it is 0.98, at the edge of the
// band (docs/validation.md, "MPM column collapse").
TEST(MpmCollapse, TallColumnsRunOutAsAPowerOfTheAspectRatio) {
  const double width = 10 * kCell;
  const Deposit three = collapse(3.0, 1.0e7, 1.0, 0.0, width);
  const Deposit six = collapse(6.0, 1.0e7, 1.1, 0.0, width);
  const double exponent =
      std::log(normalised_runout(six) / normalised_runout(three)) / std::log(2.0);
  EXPECT_NEAR(exponent, 0.9, 0.1);
  RecordProperty("runout_a3", std::to_string(normalised_runout(three)));
  RecordProperty("runout_a6", std::to_string(normalised_runout(six)));
  RecordProperty("runout_exponent", std::to_string(exponent));
  RecordProperty("height_a3", std::to_string(three.height / width));
  RecordProperty("height_a6", std::to_string(six.height / width));
}

}  // namespace
}  // namespace partimix::mpm
