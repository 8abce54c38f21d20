// The Johnson-Cook strength and damage model (docs/multi-material-sph.md, "Johnson-Cook strength
// and damage"): the flow stress and the failure strain against their formulas written out here
// for OFHC copper and 4340 steel, the clamps of rate* and T*, the damage rate of the seed's
// eq. 12, and damage integrated along a monotonic strain path reaching D_C at the failure strain.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "materials/johnson_cook.hpp"
#include "support/johnson_cook_metals.hpp"

namespace partimix::materials {
namespace {

using test_support::kRoom;
using test_support::ofhc_copper;
using test_support::steel_4340;

const std::vector<double> kStrains{0.0, 0.01, 0.1, 0.5, 1.5};
const std::vector<double> kRates{1.0, 10.0, 1.0e3, 1.0e5};  // at or above rate0 = 1/s
const std::vector<double> kTemperatures{kRoom, 400.0, 800.0, 1200.0};
const std::vector<double> kTriaxialities{-1.0 / 3.0, 0.0, 1.0 / 3.0, 2.0 / 3.0, 1.5};

void expect_relative(double actual, double expected, double tolerance) {
  EXPECT_NEAR(actual, expected, tolerance * std::abs(expected));
}

TEST(JohnsonCook, FlowStressFollowsItsFormula) {
  for (const JohnsonCookParameters& p : {ofhc_copper(), steel_4340()}) {
    for (const double r : kStrains) {
      for (const double rate : kRates) {
        for (const double t : kTemperatures) {
          const double t_star = (t - kRoom) / (p.melt_temperature - kRoom);
          const double expected = (p.A + p.B * std::pow(r, p.n)) * (1.0 + p.C * std::log(rate)) *
                                  (1.0 - std::pow(t_star, p.m));
          expect_relative(flow_stress(p, r, rate, t), expected, 1.0e-12);
        }
      }
    }
  }
}

TEST(JohnsonCook, FlowStressAtTheReferenceStateIsA) {
  const JohnsonCookParameters p = ofhc_copper();
  EXPECT_EQ(flow_stress(p, 0.0, 1.0, kRoom), 90.0e6);
}

TEST(JohnsonCook, RatesBelowTheReferenceAreClampedSoTheLogIsNonNegative) {
  const JohnsonCookParameters p = steel_4340();
  EXPECT_EQ(dimensionless_strain_rate(p, 0.0), 1.0);
  EXPECT_EQ(dimensionless_strain_rate(p, 1.0e-3), 1.0);
  EXPECT_EQ(dimensionless_strain_rate(p, 250.0), 250.0);
  for (const double rate : {0.0, 1.0e-6, 0.5}) {
    EXPECT_EQ(flow_stress(p, 0.2, rate, 500.0), flow_stress(p, 0.2, 1.0, 500.0)) << rate;
    EXPECT_EQ(failure_strain(p, 0.4, rate, 500.0), failure_strain(p, 0.4, 1.0, 500.0)) << rate;
  }
}

TEST(JohnsonCook, HomologousTemperatureIsClampedToZeroOne) {
  const JohnsonCookParameters p = ofhc_copper();
  EXPECT_EQ(homologous_temperature(p, 200.0), 0.0);
  EXPECT_EQ(homologous_temperature(p, kRoom), 0.0);
  EXPECT_DOUBLE_EQ(homologous_temperature(p, 825.0), 0.5);
  EXPECT_EQ(homologous_temperature(p, 1356.0), 1.0);
  EXPECT_EQ(homologous_temperature(p, 2000.0), 1.0);
  EXPECT_EQ(flow_stress(p, 0.3, 100.0, 200.0), flow_stress(p, 0.3, 100.0, kRoom));
  EXPECT_EQ(flow_stress(p, 0.3, 100.0, 1356.0), 0.0);  // molten: no strength
  EXPECT_EQ(flow_stress(p, 0.3, 100.0, 3000.0), 0.0);
}

TEST(JohnsonCook, FailureStrainFollowsItsFormula) {
  for (const JohnsonCookParameters& p : {ofhc_copper(), steel_4340()}) {
    for (const double triaxiality : kTriaxialities) {
      for (const double rate : kRates) {
        for (const double t : kTemperatures) {
          const double t_star = (t - kRoom) / (p.melt_temperature - kRoom);
          const double expected = (p.D1 + p.D2 * std::exp(p.D3 * triaxiality)) *
                                  (1.0 + p.D4 * std::log(rate)) * (1.0 + p.D5 * t_star);
          expect_relative(failure_strain(p, triaxiality, rate, t), expected, 1.0e-12);
        }
      }
    }
  }
  // Copper in uniaxial tension at the reference state: 0.54 + 4.89 exp(-1.01) = 2.3208...
  expect_relative(failure_strain(ofhc_copper(), 1.0 / 3.0, 1.0, kRoom),
                  0.54 + 4.89 * std::exp(-1.01), 1.0e-12);
}

TEST(JohnsonCook, FailureStrainTemperatureIsClamped) {
  const JohnsonCookParameters p = steel_4340();
  EXPECT_EQ(failure_strain(p, 0.5, 10.0, 100.0), failure_strain(p, 0.5, 10.0, kRoom));
  expect_relative(failure_strain(p, 0.5, 10.0, 5000.0), failure_strain(p, 0.5, 10.0, 1793.0),
                  1.0e-15);
}

TEST(JohnsonCook, DamageRateIsZeroUpToTheThresholdThenLinearInTheStrainRate) {
  JohnsonCookParameters p = ofhc_copper();
  p.damage_threshold = 0.1;
  p.critical_damage = 0.9;
  const double pf = 1.3;
  EXPECT_EQ(damage_rate(p, 0.0, 50.0, pf), 0.0);
  EXPECT_EQ(damage_rate(p, 0.1, 50.0, pf), 0.0);
  expect_relative(damage_rate(p, 0.1 + 1.0e-9, 50.0, pf), 0.9 / 1.2 * 50.0, 1.0e-14);
  expect_relative(damage_rate(p, 0.7, 50.0, pf), 0.9 / 1.2 * 50.0, 1.0e-14);
  EXPECT_EQ(damage_rate(p, 0.7, 0.0, pf), 0.0);
  // Past the threshold with p_f <= p_d, any plastic flow fails the material at once.
  EXPECT_EQ(damage_rate(p, 0.7, 50.0, 0.05), std::numeric_limits<double>::infinity());
  EXPECT_EQ(damage_after_step(p, 0.0, 0.7, 1.0e-6, 0.05), 1.0);
}

TEST(JohnsonCook, DamageStepIsTheIntegralOfTheDamageRate) {
  JohnsonCookParameters p = steel_4340();
  p.damage_threshold = 0.02;
  const double pf = failure_strain(p, 1.0 / 3.0, 100.0, 400.0);
  const double rate = 100.0;
  const double dt = 1.0e-6;
  for (const double r : {0.03, 0.05, 0.1}) {
    const double step = damage_after_step(p, 0.2, r, rate * dt, pf) - 0.2;
    expect_relative(step, damage_rate(p, r, rate, pf) * dt, 1.0e-9);
  }
}

// Accumulates damage over steps r_0 = 0 < r_1 < ... < r_N = p_f of uneven sizes, checking the
// linear law D(r) = D_C max(r - p_d, 0) / (p_f - p_d) at every step; returns D(p_f).
double accumulate_to_failure(const JohnsonCookParameters& p, double pf, int steps) {
  double damage = 0.0;
  double r = 0.0;
  for (int k = 1; k <= steps; ++k) {
    const double next = pf * std::pow(static_cast<double>(k) / steps, 1.7);
    damage = damage_after_step(p, damage, r, next - r, pf);
    r = next;
    const double expected =
        p.critical_damage * std::max(r - p.damage_threshold, 0.0) / (pf - p.damage_threshold);
    EXPECT_NEAR(damage, std::min(expected, 1.0), 1.0e-13) << "step " << k << ", r = " << r;
  }
  return damage;
}

TEST(JohnsonCook, DamageReachesOneAtTheFailureStrainWithoutThreshold) {
  const JohnsonCookParameters p = ofhc_copper();
  const double pf = failure_strain(p, 1.0 / 3.0, 1.0e3, 500.0);
  const double damage = accumulate_to_failure(p, pf, 137);
  EXPECT_NEAR(damage, 1.0, 1.0e-13);
  EXPECT_LE(damage, 1.0);
}

TEST(JohnsonCook, DamageReachesOneAtTheFailureStrainWithThreshold) {
  JohnsonCookParameters p = steel_4340();
  p.damage_threshold = 0.3 * failure_strain(p, 0.5, 10.0, kRoom);
  const double pf = failure_strain(p, 0.5, 10.0, kRoom);
  EXPECT_NEAR(accumulate_to_failure(p, pf, 61), 1.0, 1.0e-13);
}

TEST(JohnsonCook, DamageIsCappedAtOne) {
  JohnsonCookParameters p = ofhc_copper();
  p.critical_damage = 0.8;  // D = 0.8 at p_f, 1 at p_f + 0.25 (p_f - p_d)
  const double pf = 2.0;
  EXPECT_NEAR(damage_after_step(p, 0.0, 0.0, pf, pf), 0.8, 1.0e-15);
  EXPECT_NEAR(damage_after_step(p, 0.0, 0.0, 2.4, pf), 0.96, 1.0e-15);
  EXPECT_EQ(damage_after_step(p, 0.0, 0.0, 2.5, pf), 1.0);
  EXPECT_EQ(damage_after_step(p, 0.0, 0.0, 10.0, pf), 1.0);
  EXPECT_EQ(damage_after_step(p, 1.0, 3.0, 0.5, pf), 1.0);
  EXPECT_EQ(damage_after_step(p, 0.5, 1.0, 0.0, pf), 0.5);  // no flow, no damage
}

}  // namespace
}  // namespace partimix::materials
