// The J2 radial return (docs/multi-material-sph.md, "Radial return"): elastic trial states stay
// unchanged; perfect plasticity lands exactly on the yield surface with dr = (sigma_trial -
// sigma_y) / (3 G); linear hardening matches its closed form; the return is deviatoric and
// coaxial with the trial; a Johnson-Cook yield stress (infinite slope at r = 0, rate dependent)
// satisfies the consistency condition to round-off.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "materials/johnson_cook.hpp"
#include "materials/radial_return.hpp"
#include "support/johnson_cook_metals.hpp"

namespace partimix::materials {
namespace {

constexpr double kShearModulus = 80.0e9;  // [Pa]
constexpr double kYield = 300.0e6;        // [Pa]

// Traceless symmetric directions: uniaxial, pure shear, and a general one.
std::vector<Mat3> directions() {
  Mat3 uniaxial = Mat3::Zero();
  uniaxial.diagonal() << 2.0, -1.0, -1.0;
  Mat3 shear = Mat3::Zero();
  shear(0, 1) = shear(1, 0) = 1.0;
  Mat3 general;
  general << 0.7, 0.3, -0.2, 0.3, -1.1, 0.5, -0.2, 0.5, 0.4;
  return {uniaxial, shear, general};
}

// The direction scaled to von Mises stress `equivalent`.
Mat3 with_equivalent_stress(const Mat3& direction, double equivalent) {
  return direction * (equivalent / von_mises_stress(direction));
}

YieldFunction perfectly_plastic(double yield) {
  return [yield](double) { return YieldPoint{yield, 0.0}; };
}

TEST(RadialReturn, VonMisesStressOfUniaxialDeviator) {
  // Uniaxial stress sigma: S = sigma diag(2/3, -1/3, -1/3), sqrt(3/2 S:S) = sigma.
  Mat3 s = Mat3::Zero();
  s.diagonal() << 2.0 / 3.0, -1.0 / 3.0, -1.0 / 3.0;
  EXPECT_NEAR(von_mises_stress(250.0e6 * s), 250.0e6, 1.0e-6);
}

TEST(RadialReturn, ElasticTrialIsUnchanged) {
  for (const Mat3& d : directions()) {
    for (const double ratio : {0.0, 0.5, 1.0}) {
      const Mat3 trial = with_equivalent_stress(d, ratio * kYield);
      const RadialReturnResult a = radial_return(trial, kShearModulus, kYield, 1.0e9);
      const RadialReturnResult b = radial_return(trial, kShearModulus, perfectly_plastic(kYield));
      EXPECT_EQ(a.deviatoric_stress, trial);
      EXPECT_EQ(b.deviatoric_stress, trial);
      EXPECT_EQ(a.plastic_strain_increment, 0.0);
      EXPECT_EQ(b.plastic_strain_increment, 0.0);
    }
  }
}

TEST(RadialReturn, PerfectlyPlasticReturnsOntoTheYieldSurface) {
  for (const Mat3& d : directions()) {
    for (const double ratio : {1.0 + 1.0e-9, 1.001, 2.0, 100.0}) {
      const Mat3 trial = with_equivalent_stress(d, ratio * kYield);
      const double trial_equivalent = von_mises_stress(trial);  // as rounded in `trial`
      const double expected_dr = (trial_equivalent - kYield) / (3.0 * kShearModulus);
      for (const RadialReturnResult& r :
           {radial_return(trial, kShearModulus, kYield, 0.0),
            radial_return(trial, kShearModulus, perfectly_plastic(kYield))}) {
        EXPECT_NEAR(von_mises_stress(r.deviatoric_stress), kYield, 1.0e-14 * kYield);
        EXPECT_NEAR(r.plastic_strain_increment, expected_dr, 1.0e-12 * expected_dr)
            << "ratio " << ratio;
      }
    }
  }
}

TEST(RadialReturn, LinearHardeningMatchesTheClosedForm) {
  const double h = 2.0e9;  // hardening modulus [Pa]
  const auto linear = [h](double dr) { return YieldPoint{kYield + h * dr, h}; };
  for (const Mat3& d : directions()) {
    for (const double ratio : {1.01, 3.0, 30.0}) {
      const Mat3 trial = with_equivalent_stress(d, ratio * kYield);
      const double trial_equivalent = von_mises_stress(trial);
      const double dr = (trial_equivalent - kYield) / (3.0 * kShearModulus + h);
      const double yield = kYield + h * dr;
      for (const RadialReturnResult& r : {radial_return(trial, kShearModulus, kYield, h),
                                          radial_return(trial, kShearModulus, linear)}) {
        EXPECT_NEAR(r.plastic_strain_increment, dr, 1.0e-12 * dr);
        EXPECT_NEAR(von_mises_stress(r.deviatoric_stress), yield, 1.0e-14 * yield);
        EXPECT_NEAR(von_mises_stress(r.deviatoric_stress),
                    trial_equivalent - 3.0 * kShearModulus * r.plastic_strain_increment,
                    1.0e-12 * yield);
      }
    }
  }
}

TEST(RadialReturn, ReturnedStressIsDeviatoricAndCoaxial) {
  for (const Mat3& d : directions()) {
    const Mat3 trial = with_equivalent_stress(d, 5.0 * kYield);
    const Mat3 s = radial_return(trial, kShearModulus, kYield, 1.0e9).deviatoric_stress;
    const double scale = trial.norm();
    EXPECT_NEAR(s.trace(), 0.0, 1.0e-15 * scale);
    // s = lambda trial with lambda = (s : trial) / (trial : trial) in (0, 1).
    const double lambda = (s.array() * trial.array()).sum() / trial.squaredNorm();
    EXPECT_GT(lambda, 0.0);
    EXPECT_LT(lambda, 1.0);
    EXPECT_LT((s - lambda * trial).norm(), 1.0e-15 * scale);
    EXPECT_LT((s * trial - trial * s).norm(), 1.0e-15 * scale * scale);  // same eigenvectors
    EXPECT_LT((s - s.transpose()).norm(), 1.0e-15 * scale);
  }
}

// 4340 steel (Johnson & Cook 1983) from a virgin state, r = 0, where d sigma_y / dr = B n r^(n-1)
// is infinite, at dt = 1 us and room temperature: sigma_y(dr) = flow_stress(dr, dr / dt, T).
TEST(RadialReturn, SolvesTheJohnsonCookConsistencyCondition) {
  const JohnsonCookParameters p = test_support::steel_4340();
  const double dt = 1.0e-6;
  const double t = 600.0;
  int calls = 0;
  const auto yield = [&](double dr) {
    ++calls;
    const double rate = dr / dt;
    const double stress = flow_stress(p, dr, rate, t);
    const double hardening = (p.A + p.B * std::pow(dr, p.n));
    const double thermal = stress / (hardening * (1.0 + p.C * std::log(std::max(rate, 1.0))));
    const double by_strain = p.B * p.n * std::pow(dr, p.n - 1.0) * stress / hardening;
    const double by_rate = rate > 1.0 ? hardening * p.C / dr * thermal : 0.0;
    return YieldPoint{stress, by_strain + by_rate};
  };
  for (const double trial_equivalent : {0.9e9, 2.0e9, 20.0e9}) {
    calls = 0;
    const Mat3 trial = with_equivalent_stress(directions()[2], trial_equivalent);
    const RadialReturnResult r = radial_return(trial, kShearModulus, yield);
    const double dr = r.plastic_strain_increment;
    ASSERT_GT(dr, 0.0);
    const double sigma_y = flow_stress(p, dr, dr / dt, t);
    EXPECT_NEAR(trial_equivalent - 3.0 * kShearModulus * dr, sigma_y, 1.0e-12 * sigma_y);
    EXPECT_NEAR(von_mises_stress(r.deviatoric_stress), sigma_y, 1.0e-14 * sigma_y);
    EXPECT_LT(calls, 40);
    RecordProperty("yield_calls_" + std::to_string(static_cast<int>(trial_equivalent / 1e8)),
                   calls);
  }
}

}  // namespace
}  // namespace partimix::materials
