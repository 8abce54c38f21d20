// A Johnson-Cook bar in uniaxial tension at one material point (docs/multi-material-sph.md,
// "Solid"; the Johnson-Cook bar, evaluated directly): 4340 steel (Johnson & Cook
// 1983/85) stretched at a constant rate along x with the isochoric velocity gradient
// L = rate diag(1, -1/2, -1/2), the mean stress sigma_eq / 3 of a bar (triaxiality 1/3), by
// Hooke's law in the Jaumann rate and the return to the yield surface. Checked step by step:
// elastic until sigma_eq = 3 G strain reaches A; then sigma_eq = (1 - D) sigma_y(r, dr/dt, T) of
// eq. 11 to 1e-9 (with the damage of the step's start); the damage of eq. 12, summed step by step
// at each step's p_f of eq. 13 at triaxiality 1/3, to 1e-9; and the point fails (D = 1, S = 0)
// at the step where r passes p_f. A failed point stays at S = 0 under any strain, even with an
// infinite flow stress (a solid that never yields), which once gave 0 x inf.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "materials/jaumann_rate.hpp"
#include "materials/johnson_cook.hpp"
#include "materials/radial_return.hpp"
#include "sph/multi_material/solid_update.hpp"
#include "support/johnson_cook_metals.hpp"

namespace partimix::sph {
namespace {

constexpr double kShearModulus = 80.0e9;
constexpr double kRate = 100.0;  // [1/s]
constexpr double kDensity = 7830.0;
constexpr double kTemperature = 294.0;

SolidSpec steel() {
  SolidSpec solid;
  solid.shear_modulus = kShearModulus;
  solid.johnson_cook = test_support::steel_4340();
  solid.johnson_cook.damage_threshold = 0.1;
  return solid;
}

TEST(SolidUpdate, JohnsonCookBarFollowsEquations11To13) {
  const SolidSpec solid = steel();
  const materials::JohnsonCookParameters& jc = solid.johnson_cook;
  Mat3 velocity_gradient = Mat3::Zero();
  velocity_gradient.diagonal() << kRate, -0.5 * kRate, -0.5 * kRate;
  const double dt = 1e-6;
  SolidPoint point;
  double pressure = 0.0;
  bool yielded = false;
  double failure = 0.0;
  double expected_damage = 0.0;  // eq. 12 summed step by step at each step's p_f
  for (int step = 1; step <= 40000 && point.damage < 1.0; ++step) {
    const Mat3 trial = point.deviatoric_stress +
                       dt * materials::jaumann_stress_rate(point.deviatoric_stress,
                                                           velocity_gradient, kShearModulus);
    const double before = point.plastic_strain;
    const double start_damage = point.damage;
    // The bar's mean stress sigma_eq / 3 of the step's end, by fixed-point iteration.
    const SolidPoint start = point;
    SolidStepResult result;
    double equivalent = 0.0;
    for (int iteration = 0; iteration < 50; ++iteration) {
      point = start;
      result = return_to_yield(solid, trial, pressure, kTemperature, kDensity, dt, point);
      equivalent = materials::von_mises_stress(point.deviatoric_stress);
      if (std::abs(pressure + equivalent / 3.0) <= 1e-12 * equivalent)
        break;
      pressure = -equivalent / 3.0;
    }
    const double triaxiality = equivalent > 0.0 ? -pressure / equivalent : 0.0;
    if (result.plastic_strain_increment == 0.0) {
      ASSERT_FALSE(yielded) << "step " << step;
      EXPECT_NEAR(equivalent, 3.0 * kShearModulus * kRate * dt * step, 1e-9 * equivalent);
      continue;
    }
    yielded = true;
    const double rate = result.plastic_strain_increment / dt;
    if (point.damage >= 1.0) {
      EXPECT_GE(point.plastic_strain, failure);
      EXPECT_LT(before, failure);
      EXPECT_EQ(equivalent, 0.0);
      break;
    }
    failure = materials::failure_strain(jc, triaxiality, rate, kTemperature);
    ASSERT_NEAR(triaxiality, 1.0 / 3.0, 1e-9);
    expected_damage += std::max(0.0, point.plastic_strain - std::max(before, jc.damage_threshold)) /
                       (failure - jc.damage_threshold);
    ASSERT_NEAR(point.damage, expected_damage, 1e-9) << "step " << step;
    const double yield =
        (1.0 - start_damage) * materials::flow_stress(jc, point.plastic_strain, rate, kTemperature);
    ASSERT_NEAR(equivalent, yield, 1e-9 * yield) << "step " << step;
  }
  EXPECT_TRUE(yielded);
  EXPECT_GE(point.damage, 1.0);
  EXPECT_NEAR(point.plastic_strain, failure, kRate * dt * 1.01);
}

TEST(SolidUpdate, FailedPointCarriesNoDeviatoricStress) {
  for (const double yield :
       {test_support::steel_4340().A, std::numeric_limits<double>::infinity()}) {
    SolidSpec solid = steel();
    solid.johnson_cook.A = yield;
    SolidPoint point;
    point.damage = 1.0;
    Mat3 trial = Mat3::Zero();
    trial(0, 1) = trial(1, 0) = 1.0e8;
    const SolidStepResult result =
        return_to_yield(solid, trial, -1.0e8, kTemperature, kDensity, 1e-6, point);
    EXPECT_EQ(point.deviatoric_stress, Mat3::Zero()) << yield;
    EXPECT_EQ(result.plastic_work, 0.0) << yield;
    EXPECT_EQ(point.damage, 1.0) << yield;
  }
}

}  // namespace
}  // namespace partimix::sph
