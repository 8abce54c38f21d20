// The seed's validation vessel (section 2, after Youcefi et al. 1997; cases/youcefi_vessel.yaml),
// Newtonian and laminar: Np = P / (rho N^3 d^5) falls as 1/Re, Re = rho N d^2 / mu (eqs. 25-26).
// The test runs the case file at Re = 0.5, 1, 5 and 10 by changing the viscosity at N = 60
// rpm (so the tip speed and c0 stay fixed), coarse enough for ctest: dp = 20 mm, about 7,000
// particles. The plate is thickened to 60 mm = 2h, so that it is watertight: a plate one spacing
// thick is seen through by the fluid (docs/geometry-meshes.md, "Bodies thinner than the kernel
// support") and gave half the torque (Np Re = 97 instead of 155 at Re = 0.5). The vessel is
// closed by a lid at the fill height: without gravity (the case leaves it out, as the seed does
// for the power curve) a free surface would let the centrifugal force (omega^2 r = 6 m/s^2 at
// N = 1 r/s) empty the vessel's centre. Np is the mean over the last half revolution, after a
// few viscous times of the plate, (d/2)^2 / nu = Re / (4 N). Asserted: the fitted slope of
// log Np on log Re within 0.1 of -1 and every Np Re within 10% of their mean (the issue's
// tolerances). Measured figures are in docs/power.md ("Validation").
// Measured (2026-11-27, this test, one thread, 130 s): Np Re = 209.1, 213.2, 225.1, 229.9 at
// Re = 0.5, 1, 5, 10; fitted slope -0.968; spread -4.6% / +4.8% about the mean 219.3. Np Re
// still rises with Re, by 9.9%, where the experiment is flat (slope -0.997); 13.5% before the
// plate's uniform pressure was taken from its own particles (docs/power.md, "Uniform parts of
// the load"). At finer spacings the weakly-compressible rise grows (17.9% at dp = 10 mm, 23% at
// 7.5 mm) and the incompressible scheme's shrinks (7.1%, 1.6%); neither constant is converged
// (docs/power.md, "Validation").
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "io/case.hpp"
#include "support/case_run.hpp"

namespace partimix {
namespace {

constexpr double kDensity = 1260.0;
constexpr double kDiameter = 0.15;
constexpr double kSpeed = 1.0;  // N [r/s]

struct Point {
  double reynolds = 0.0;
  double end_time = 0.0;  // [s]
};

// The case at Re = point.reynolds (the viscosity set at N = 60 rpm), with a lid at the fill
// height, the plate of the given thickness, and `extra` overrides; Np over the last `window`
// revolutions.
double power_number_at(const Point& point, double spacing, double plate_width, double window,
                       const std::vector<std::string>& extra) {
  const double viscosity = kDensity * kSpeed * kDiameter * kDiameter / point.reynolds;
  std::vector<std::string> overrides{"sph.spacing=" + std::to_string(spacing),
                                     "sph.max_velocity=0.5",
                                     "walls[1].width=" + std::to_string(plate_width),
                                     "walls[0].open=[]",
                                     "walls[0].height=0.3",
                                     "walls[1].height=0.28",
                                     "walls[1].motion.rpm=60",
                                     "walls[1].motion.ramp_time=0.05",
                                     "fluid.viscosity=" + std::to_string(viscosity),
                                     "time.end=" + std::to_string(point.end_time),
                                     "time.sample_interval=0.02",
                                     "output.frames=false",
                                     "analyses[0].average_revolutions=" + std::to_string(window)};
  overrides.insert(overrides.end(), extra.begin(), extra.end());
  const io::Case the_case =
      io::load_case(std::string(PARTIMIX_SOURCE_DIR) + "/cases/youcefi_vessel.yaml", overrides);
  const test_support::CaseRun run = test_support::run_case(the_case);
  EXPECT_EQ(run.summary.status, "completed");
  EXPECT_NEAR(run.figures.at("Re"), point.reynolds, 1e-6 * point.reynolds);
  return run.figures.at("Np");
}

double power_number_at(const Point& point) {
  return power_number_at(point, 0.02, 0.06, 0.5, {});
}

TEST(StirredVessel, PowerNumberFallsAsOneOverReynoldsInLaminarFlow) {
  const std::vector<Point> points{{0.5, 1.0}, {1.0, 1.0}, {5.0, 2.0}, {10.0, 3.0}};
  std::vector<double> log_re;
  std::vector<double> log_np;
  std::vector<double> np_re;
  for (const Point& point : points) {
    const double np = power_number_at(point);
    std::printf("Re %5.2f: Np %.4g, Np Re %.4g\n", point.reynolds, np, np * point.reynolds);
    log_re.push_back(std::log(point.reynolds));
    log_np.push_back(std::log(np));
    np_re.push_back(np * point.reynolds);
  }
  const auto n = static_cast<double>(points.size());
  double mean_x = 0.0;
  double mean_y = 0.0;
  for (std::size_t k = 0; k < points.size(); ++k) {
    mean_x += log_re[k] / n;
    mean_y += log_np[k] / n;
  }
  double sxy = 0.0;
  double sxx = 0.0;
  for (std::size_t k = 0; k < points.size(); ++k) {
    sxy += (log_re[k] - mean_x) * (log_np[k] - mean_y);
    sxx += (log_re[k] - mean_x) * (log_re[k] - mean_x);
  }
  const double slope = sxy / sxx;
  double mean_np_re = 0.0;
  for (const double value : np_re)
    mean_np_re += value / n;
  std::printf("fitted slope %.4f, mean Np Re %.4g\n", slope, mean_np_re);
  EXPECT_NEAR(slope, -1.0, 0.1);
  for (const double value : np_re)
    EXPECT_NEAR(value / mean_np_re, 1.0, 0.1);
}

// The incompressible scheme against the finite-element torque of the same vessel
// (tools/vessel_flow_reference.py; docs/power.md, "The vessel in 3D: a finite-element
// reference"): the test's 30 mm plate in Stokes flow, Np Re = 306 (306.84, 306.35, 305.99 with
// elements of 6, 4 and 3 mm at the plate's edges). Re = 0.5, where inertia adds 0.03% in 2D; the
// extrapolated ghost velocity; runs to 0.4 s, Np over the last 0.2 revolutions (steady: at
// dp = 7.5 mm the 1-s run's mean is within 0.5% of it). Measured (2026-11-28, this test): Np Re
// 236.8 at dp = 10 mm (-22.6%) and 265.5 at 7.5 mm (-13.2%); 296.9 at 5 mm (-3.0%, not run
// here: 51 minutes). Asserted: at dp = 7.5 mm within 17% of the reference, and the error at most
// 3/4 of that at dp = 10 mm, which first-order convergence would give (measured 0.59). About
// 4.2 minutes on one core (5.5 before the multigrid lumped its finest operator's weak couplings).
TEST(StirredVessel, IncompressibleTorqueConvergesToTheFiniteElementOne) {
  constexpr double kReference = 306.0;
  const std::vector<std::string> incompressible{
      "sph.scheme=incompressible", "sph.viscosity_integration=implicit",
      "sph.shifting.model=fickian", "sph.time_step.flow_cfl=0.2", "sph.wall_velocity=extrapolated"};
  const Point point{0.5, 0.4};
  const double coarse = power_number_at(point, 0.01, 0.03, 0.2, incompressible) * point.reynolds;
  const double fine = power_number_at(point, 0.0075, 0.03, 0.2, incompressible) * point.reynolds;
  const double coarse_error = coarse / kReference - 1.0;
  const double fine_error = fine / kReference - 1.0;
  std::printf("Np Re %.4g (dp 10 mm, %+.2f%%), %.4g (dp 7.5 mm, %+.2f%%) against %.4g\n", coarse,
              100.0 * coarse_error, fine, 100.0 * fine_error, kReference);
  EXPECT_LT(std::abs(fine_error), 0.17);
  EXPECT_LT(std::abs(fine_error), 0.75 * std::abs(coarse_error));
}

}  // namespace
}  // namespace partimix
