// Elastic checks of the MPM method (docs/mpm.md; docs/validation.md, "MPM"):
// 1. A laterally confined column (periodic in x) on a rough floor, released stress-free under
//    gravity, vibrates in its first mode with period T = 4 H / c, c = sqrt((K + 4G/3) / rho)
//    (the P-wave speed of uniaxial strain), about the static compression of its top
//    rho g H^2 / (2 (K + 4G/3)). Tolerances: 3% on the half period, 3% on the mean.
// 2. A column started in geostatic equilibrium between slip walls stays at rest: speeds below
//    5e-3 sqrt(g H), and sigma_yy = -rho g (H - y) within 2% of rho g H (RMS) above the two
//    cells next to the rough floor. In those two cells the error is 12% (RMS; 15% asserted as a
//    regression guard): the B-splines' boundary error, a known weakness (docs/mpm.md, "Known
//    weaknesses").
// 3. The cell-crossing test: a soft confined column whose top falls about 6 cells under its
//    own weight. The exact sigma_yy is smooth in y but for the wave front; the row-to-row
//    roughness of the points' stress (the median over the rows) is the cell-crossing noise
//    (Bardenhagen & Kober 2004). With the default quadratic B-splines it stays below 1% of
//    rho g H; with linear shape functions it is at least 3 times larger, which is why
//    B-splines are the default.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "support/mpm_setups.hpp"

namespace partimix::mpm {
namespace {

using test_support::box_fill;
using test_support::domain_2d;
using test_support::mpm_config;
using test_support::plane_wall;
using test_support::seed_beads;

const Vec3 kGravity(0.0, -9.81, 0.0);
constexpr double kCell = 0.005;

materials::GranularMaterial elastic_beads() {
  materials::GranularMaterial m = seed_beads(1.0e7);
  m.mu_s = 1.0e3;  // never yields: the elastic response alone
  m.mu_2 = 1.0e3;
  return m;
}

double mean_top(const ParticleStore& store, double from) {
  double sum = 0.0;
  int count = 0;
  for (const Vec3& x : store.position()) {
    if (x.y() > from) {
      sum += x.y();
      ++count;
    }
  }
  return sum / count;
}

TEST(MpmElastic, VibratingColumnHasThePeriodFourHOverC) {
  const double height = 0.2;
  const materials::GranularMaterial m = elastic_beads();
  MpmConfig config = mpm_config(kCell, m);
  config.fills = {box_fill(Vec3(0, 0, -1), Vec3(3 * kCell, height, 1), kCell / 2)};
  config.walls = {plane_wall(Vec3::Zero(), Vec3::UnitY(), GridBoundary::no_slip)};
  ParticleStore store;
  MpmSolver solver(store, domain_2d(Vec3::Zero(), Vec3(3 * kCell, 0.25, 0), true), config, kGravity,
                   {});
  const double modulus = m.bulk_modulus() + 4.0 * m.shear_modulus() / 3.0;
  const double period = 4.0 * height / std::sqrt(modulus / m.density);
  const double static_drop = m.density * 9.81 * height * height / (2.0 * modulus);
  const double top0 = mean_top(store, height - kCell);
  double lowest = 0.0;
  double lowest_time = 0.0;
  double mean_drop = 0.0;
  while (solver.time() < period) {
    const double dt = solver.stable_dt();
    solver.step(dt);
    const double drop = top0 - mean_top(store, height - kCell);
    mean_drop += drop * dt;
    if (drop > lowest) {
      lowest = drop;
      lowest_time = solver.time();
    }
  }
  mean_drop /= solver.time();
  EXPECT_NEAR(lowest_time, 0.5 * period, 0.03 * 0.5 * period);
  EXPECT_NEAR(mean_drop, static_drop, 0.03 * static_drop);
  RecordProperty("half_period_ratio", std::to_string(lowest_time / (0.5 * period)));
  RecordProperty("mean_drop_ratio", std::to_string(mean_drop / static_drop));
}

// RMS of sigma_yy + rho g (H - y) over the points with y in [from, to), relative to rho g H.
double stress_error(const ParticleStore& store, double height, double from, double to) {
  const auto& normal = store.find_vector("stress_normal")->values;
  double sum = 0.0;
  int count = 0;
  for (std::size_t p = 0; p < store.size(); ++p) {
    const double y = store.position()[p].y();
    if (y < from || y >= to)
      continue;
    const double exact = -2200.0 * 9.81 * (height - y);
    sum += (normal[p].y() - exact) * (normal[p].y() - exact);
    ++count;
  }
  return std::sqrt(sum / count) / (2200.0 * 9.81 * height);
}

TEST(MpmElastic, GeostaticColumnStaysAtRest) {
  const double height = 0.2;
  MpmConfig config = mpm_config(kCell, seed_beads(1.0e7));
  PointFill fill = box_fill(Vec3(0, 0, -1), Vec3(0.1, height, 1), kCell / 2);
  fill.geostatic = true;
  config.fills = {fill};
  config.walls = {plane_wall(Vec3::Zero(), Vec3::UnitY(), GridBoundary::no_slip),
                  plane_wall(Vec3::Zero(), Vec3::UnitX(), GridBoundary::slip),
                  plane_wall(Vec3(0.1, 0, 0), -Vec3::UnitX(), GridBoundary::slip)};
  ParticleStore store;
  MpmSolver solver(store, domain_2d(Vec3::Zero(), Vec3(0.1, 0.25, 0)), config, kGravity, {});
  double fastest = 0.0;
  while (solver.time() < 0.05) {
    solver.step(solver.stable_dt());
    for (const Vec3& v : store.velocity())
      fastest = std::max(fastest, v.norm());
  }
  EXPECT_LT(fastest, 5e-3 * std::sqrt(9.81 * height));
  const double interior = stress_error(store, height, 2 * kCell, height);
  const double floor_layer = stress_error(store, height, 0.0, 2 * kCell);
  EXPECT_LT(interior, 0.02);
  EXPECT_LT(floor_layer, 0.15);  // measured 0.117: a known weakness, a regression guard here
  RecordProperty("fastest_over_sqrt_gH", std::to_string(fastest / std::sqrt(9.81 * height)));
  RecordProperty("interior_rms_error", std::to_string(interior));
  RecordProperty("floor_layer_rms_error", std::to_string(floor_layer));
}

// The noise of sigma_yy in a soft confined column (rho g H / (K + 4G/3) = 0.16) released
// under its own weight for half a period, its top falling about 6 cells. The points of one
// lattice row keep the same height (the column is uniform in x); noise is what a row's mean
// sigma_yy departs from the mean of its two neighbour rows, whose smooth part is of order
// (spacing / H)^2 of rho g H. The median over the rows leaves out the wave front of the sudden
// load (a jump over a row or two). Returns the largest median over the run, relative to
// rho g H.
double crossing_noise(const std::string& shape_function) {
  const double height = 0.2;
  const double spacing = kCell / 2;
  materials::GranularMaterial soft = elastic_beads();
  soft.youngs_modulus = 2.0e5;
  MpmConfig config = mpm_config(kCell, soft);
  config.shape_function = shape_function;
  config.fills = {box_fill(Vec3(0, 0, -1), Vec3(3 * kCell, height, 1), spacing)};
  config.walls = {plane_wall(Vec3::Zero(), Vec3::UnitY(), GridBoundary::no_slip)};
  ParticleStore store;
  MpmSolver solver(store, domain_2d(Vec3::Zero(), Vec3(3 * kCell, 0.25, 0), true), config, kGravity,
                   {});
  const int rows = static_cast<int>(std::lround(height / spacing));
  std::vector<int> row_of(store.size());
  for (std::size_t p = 0; p < store.size(); ++p)
    row_of[p] = static_cast<int>(std::floor(store.position()[p].y() / spacing));
  const double modulus = soft.bulk_modulus() + 4.0 * soft.shear_modulus() / 3.0;
  const double half_period = 2.0 * height / std::sqrt(modulus / soft.density);
  const auto& normal = store.find_vector("stress_normal")->values;
  double worst = 0.0;
  std::vector<double> mean(static_cast<std::size_t>(rows));
  std::vector<double> departures;
  for (int step = 0; solver.time() < half_period; ++step) {
    solver.step(solver.stable_dt());
    std::fill(mean.begin(), mean.end(), 0.0);
    for (std::size_t p = 0; p < store.size(); ++p)
      mean[static_cast<std::size_t>(row_of[p])] += normal[p].y() / 6.0;  // 6 points a row
    departures.clear();
    for (std::size_t k = 1; k + 1 < mean.size(); ++k)
      departures.push_back(std::abs(mean[k] - 0.5 * (mean[k - 1] + mean[k + 1])));
    std::nth_element(departures.begin(), departures.begin() + departures.size() / 2,
                     departures.end());
    worst = std::max(worst, departures[departures.size() / 2] / (soft.density * 9.81 * height));
  }
  return worst;
}

TEST(MpmElastic, BsplinesDoNotRingWhenPointsCrossCells) {
  const double bspline = crossing_noise("bspline");
  const double linear = crossing_noise("linear");
  EXPECT_LT(bspline, 0.01);
  EXPECT_GT(linear, 3.0 * bspline);
  RecordProperty("bspline_rms_noise", std::to_string(bspline));
  RecordProperty("linear_rms_noise", std::to_string(linear));
}

}  // namespace
}  // namespace partimix::mpm
