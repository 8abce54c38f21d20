// Power and Reynolds numbers (docs/power.md; the seed's eqs. 25-31): the velocity and length
// scales of single-axis and planetary motion, the refusals, Re for a Newtonian and a power-law
// fluid (Metzner-Otto, eq. 27), Np = P / (rho V^3 L^2), and the power_number analysis on a
// hand-built rotor: its columns, one sample, omega from the motion's pose, and the mean over the
// last revolution.
#include "analysis/power_number.hpp"

#include <gtest/gtest.h>

#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "load_fixtures.hpp"

namespace partimix::analysis {
namespace {

using analysis_test::kPi;
using analysis_test::kRotorAxis;
using analysis_test::kRotorRpm;
using analysis_test::kRotorVessel;
using analysis_test::MovingBody;
using analysis_test::planetary;
using analysis_test::rotation;
using analysis_test::RotorStore;
using analysis_test::sample_once;

constexpr double kTight = 1e-12;

TEST(PowerScales, RotationUsesTipScaleNdAndTheDiameter) {
  // 90 rpm = 1.5 r/s, d = 0.15 m: V = N d = 0.225 m/s, L = d.
  const PowerScales scales = power_scales(rotation(Vec3::Zero(), 90.0), 0.15);
  EXPECT_NEAR(scales.velocity, 0.225, kTight);
  EXPECT_DOUBLE_EQ(scales.length, 0.15);
}

TEST(PowerScales, RotationTakesTheMagnitudeOfANegativeSpeed) {
  // -90 rpm turns clockwise; |N| = 1.5 r/s gives the same V = 0.225 m/s.
  const PowerScales scales = power_scales(rotation(Vec3::Zero(), -90.0), 0.15);
  EXPECT_NEAR(scales.velocity, 0.225, kTight);
  EXPECT_DOUBLE_EQ(scales.length, 0.15);
}

TEST(PowerScales, PlanetaryUsesUchAndTwiceTheRevolutionRadius) {
  // Own axis through (0.03, 0.04, 0.5), vessel axis through the origin, both along z: the
  // offset normal to the axis is (0.03, 0.04), e'' = 0.05 m, d_G = 0.1 m (the 0.5 along the
  // axis does not count). N_G = 30/60 = 0.5 r/s, N_R = 60/60 = 1 r/s, d_R = 0.08 m:
  // u_ch = 0.5 0.1 + 1 0.08 = 0.13 m/s (eq. 31), L = d_G.
  const PowerScales scales =
      power_scales(planetary(Vec3(0.03, 0.04, 0.5), Vec3::Zero(), 60.0, 30.0), 0.08);
  EXPECT_NEAR(scales.velocity, 0.13, kTight);
  EXPECT_NEAR(scales.length, 0.1, kTight);
}

TEST(PowerScales, PlanetaryRevolutionRadiusIsMeasuredNormalToAnyAxis) {
  // Axis along x: the offset (0.7, 0.03, 0.04) has the part (0, 0.03, 0.04) normal to it,
  // e'' = 0.05, d_G = 0.1. A counter-rotating revolution N_G = -25/60 r/s with N_R = 1 r/s,
  // d_R = 0.08: u_ch = -0.1 25/60 + 0.08 = 0.08 - 0.041666... = 0.038333... m/s.
  geometry::MotionConfig motion = planetary(Vec3(0.7, 0.03, 0.04), Vec3::Zero(), 60.0, -25.0);
  motion.axis = Vec3::UnitX();
  const PowerScales scales = power_scales(motion, 0.08);
  EXPECT_NEAR(scales.velocity, 0.08 - 0.1 * 25.0 / 60.0, kTight);
  EXPECT_NEAR(scales.length, 0.1, kTight);
}

TEST(PowerScales, RefusesBodiesThatDoNotTurn) {
  EXPECT_THROW(power_scales(geometry::MotionConfig{}, 0.1), std::invalid_argument);  // fixed
  EXPECT_THROW(power_scales(rotation(Vec3::Zero(), 0.0), 0.1), std::invalid_argument);
}

TEST(PowerScales, RefusesANonPositiveDiameter) {
  const geometry::MotionConfig turning = rotation(Vec3::Zero(), 60.0);
  EXPECT_THROW(power_scales(turning, 0.0), std::invalid_argument);
  EXPECT_THROW(power_scales(turning, -0.1), std::invalid_argument);
}

TEST(PowerScales, RefusesPlanetaryMotionWithoutAPositiveUch) {
  // e'' = 0.05 exactly, d_G = 0.1; N_G = -1 r/s, N_R = 1 r/s.
  const geometry::MotionConfig motion = planetary(Vec3(0.05, 0, 0), Vec3::Zero(), 60.0, -60.0);
  // d_R = 0.05: u_ch = -0.1 + 0.05 = -0.05 < 0.
  EXPECT_THROW(power_scales(motion, 0.05), std::invalid_argument);
  // d_R = 0.1: u_ch = -0.1 + 0.1 = 0, exactly.
  EXPECT_THROW(power_scales(motion, 0.1), std::invalid_argument);
  // The own axis on the vessel axis: e'' = 0, no length scale, although u_ch = 1 0.08 > 0.
  EXPECT_THROW(power_scales(planetary(Vec3::Zero(), Vec3::Zero(), 60.0, 30.0), 0.08),
               std::invalid_argument);
}

TEST(ReynoldsNumber, NewtonianIsRhoNd2OverMu) {
  // rho 1000, mu 0.5, N = 2 r/s, d = 0.1: Re = 1000 2 0.01 / 0.5 = 40. The Metzner-Otto
  // constant enters as k^(n - 1) = k^0 = 1.
  const PowerScales scales{2.0 * 0.1, 0.1};
  EXPECT_NEAR(reynolds_number({1000.0, 0.5, 1.0}, 7.54, scales), 40.0, 40.0 * kTight);
  EXPECT_NEAR(reynolds_number({1000.0, 0.5, 1.0}, 11.0, scales), 40.0, 40.0 * kTight);
}

TEST(ReynoldsNumber, PowerLawFollowsMetznerOttoEq27) {
  // The seed's CMC: n = 0.47, K_s = 13.9 Pa s^n, k = 7.54; rho 1600, N = 90 rpm = 1.5 r/s,
  // d = 0.15 m. Re = rho N^(2-n) d^2 / (K_s k^(n-1)) with
  //   N^1.53   = exp(1.53 ln 1.5)    = exp(0.6203616)  = 1.8596004
  //   k^-0.53  = exp(-0.53 ln 7.54)  = exp(-1.0707178) = 0.3427624
  //   Re = 1600 1.8596004 0.0225 / (13.9 0.3427624) = 66.945614 / 4.7643974 = 14.051223.
  const double n = 0.47;
  const PowerScales scales = power_scales(rotation(Vec3::Zero(), 90.0), 0.15);
  EXPECT_NEAR(reynolds_number({1600.0, 13.9, n}, 7.54, scales), 14.051223, 1e-6);
}

TEST(PowerNumber, IsPowerOverRhoV3L2) {
  // P = 3 W, rho 1000, V = 0.2 m/s, L = 0.1 m: Np = 3 / (1000 0.008 0.01) = 37.5.
  EXPECT_NEAR(power_number(3.0, 1000.0, {0.2, 0.1}), 37.5, 37.5 * kTight);
}

TEST(PowerNumber, SingleAxisIsTheSeedsEq26) {
  // Gamma = 0.05 N m at N = 2 r/s, d = 0.1, rho 1000: P = 2 pi N Gamma = 0.2 pi W and
  // Np = 2 pi N Gamma / (rho N^3 d^5) = 0.2 pi / (1000 8 1e-5) = 2.5 pi.
  const PowerScales scales = power_scales(rotation(Vec3::Zero(), 120.0), 0.1);
  EXPECT_NEAR(power_number(2.0 * kPi * 2.0 * 0.05, 1000.0, scales), 2.5 * kPi, 1e-11);
}

// The power_number analysis of the rotor of load_fixtures.hpp (body 0, 120 rpm, N = 2 r/s),
// d = 0.1 m, rho 1000, mu 0.01: V = 0.2 m/s, L = 0.1 m, rho V^3 L^2 = 1000 0.008 0.01 = 0.08 W,
// Re = 1000 2 0.01 / 0.01 = 2000.
AnalysisOptions rotor_options(const MovingBody& body) {
  AnalysisOptions options;
  options.body = body.options;
  options.diameter = 0.1;
  options.fluid = {1000.0, 0.01, 1.0};
  return options;
}

TEST(PowerNumberAnalysis, ColumnsAreReNpAndNpTotalWithoutUnits) {
  const MovingBody body(0, rotation(kRotorAxis, kRotorRpm), kRotorVessel);
  const PowerNumber analysis(rotor_options(body));
  const std::vector<Column> columns = analysis.columns();
  ASSERT_EQ(columns.size(), 3u);
  EXPECT_EQ(columns[0].name, "Re");
  EXPECT_EQ(columns[1].name, "Np");
  EXPECT_EQ(columns[2].name, "Np_total");
  for (const Column& column : columns)
    EXPECT_EQ(column.unit, "") << column.name;
  EXPECT_TRUE(analysis.needs_body_forces());
}

TEST(PowerNumberAnalysis, SampleGivesReAndNpOfTheRotor) {
  // Np = |omega Gamma_own| / 0.08 = 0.68 pi / 0.08 = 8.5 pi (= 2 pi N Gamma / (rho N^3 d^5),
  // 2 pi 2 0.17 / (1000 8 1e-5)); Np_total: the power of a pure rotation about the own axis is
  // the same, -omega . Gamma_own = 0.68 pi, so also 8.5 pi.
  const MovingBody body(0, rotation(kRotorAxis, kRotorRpm), kRotorVessel);
  PowerNumber analysis(rotor_options(body));
  const std::vector<double> values = sample_once(analysis, RotorStore(1.0).store(), 0.3);
  EXPECT_NEAR(values[0], 2000.0, 2000.0 * kTight);
  EXPECT_NEAR(values[1], 8.5 * kPi, 1e-10);
  EXPECT_NEAR(values[2], 8.5 * kPi, 1e-10);
}

TEST(PowerNumberAnalysis, ClockwiseRotationGivesTheSameNp) {
  // -120 rpm: omega = -4 pi, |omega Gamma_own| = 0.68 pi again; V = |N| d = 0.2 m/s.
  const MovingBody body(0, rotation(kRotorAxis, -kRotorRpm), kRotorVessel);
  PowerNumber analysis(rotor_options(body));
  const std::vector<double> values = sample_once(analysis, RotorStore(1.0).store(), 0.3);
  EXPECT_NEAR(values[0], 2000.0, 2000.0 * kTight);
  EXPECT_NEAR(values[1], 8.5 * kPi, 1e-10);
}

TEST(PowerNumberAnalysis, NpTakesOmegaFromThePoseDuringTheRamp) {
  // ramp_time 1 s, t = 0.5 s: speed fraction (1 - cos(pi/2))/2 = 0.5, omega = 2 pi rad/s;
  // Np = 2 pi 0.17 / 0.08 = 4.25 pi. Re keeps the full speed; Np_total takes the rigid
  // velocities of the pose too (4.25 pi).
  const MovingBody body(0, rotation(kRotorAxis, kRotorRpm, 1.0), kRotorVessel);
  PowerNumber analysis(rotor_options(body));
  const std::vector<double> values = sample_once(analysis, RotorStore(1.0).store(), 0.5);
  EXPECT_NEAR(values[0], 2000.0, 2000.0 * kTight);
  EXPECT_NEAR(values[1], 4.25 * kPi, 1e-10);
  EXPECT_NEAR(values[2], 4.25 * kPi, 1e-10);
}

TEST(PowerNumberAnalysis, FiguresAreMeansOverTheLastRevolution) {
  // A = 8.5 pi, B = 17 pi (loads doubled from t = 0.75): Np = (A + 3 B)/4 = 59.5 pi / 4;
  // Np_total the same (a pure rotation). Re is constant.
  const MovingBody body(0, rotation(kRotorAxis, kRotorRpm), kRotorVessel);
  PowerNumber analysis(rotor_options(body));
  analysis_test::sample_step_history(analysis, RotorStore(1.0).store(), RotorStore(2.0).store());
  Figures figures;
  analysis.add_figures(figures);
  EXPECT_NEAR(figures.at("Re"), 2000.0, 1e-9);
  EXPECT_NEAR(figures.at("Np"), 59.5 * kPi / 4.0, 1e-10);
  EXPECT_NEAR(figures.at("Np_total"), 59.5 * kPi / 4.0, 1e-10);
  EXPECT_DOUBLE_EQ(figures.at("average_from"), 0.5);
  EXPECT_DOUBLE_EQ(figures.at("average_to"), 1.0);
  EXPECT_DOUBLE_EQ(figures.at("average_revolutions"), 1.0);
  EXPECT_EQ(figures.size(), 6u);
}

TEST(PowerNumberAnalysis, AWindowLongerThanTheRunStartsAtTheFirstSample) {
  // average_revolutions 3: 1.5 s before t = 1 lies before the first sample, so the window is
  // [0, 1], 2 revolutions: Np = (5 A + 3 B)/8 = (42.5 + 51) pi / 8 = 11.6875 pi.
  const MovingBody body(0, rotation(kRotorAxis, kRotorRpm), kRotorVessel, 3.0);
  PowerNumber analysis(rotor_options(body));
  analysis_test::sample_step_history(analysis, RotorStore(1.0).store(), RotorStore(2.0).store());
  Figures figures;
  analysis.add_figures(figures);
  EXPECT_NEAR(figures.at("Np"), 11.6875 * kPi, 1e-10);
  EXPECT_DOUBLE_EQ(figures.at("average_from"), 0.0);
  EXPECT_DOUBLE_EQ(figures.at("average_revolutions"), 2.0);
}

TEST(PowerNumberAnalysis, ConstructionRefusesAFixedBody) {
  const MovingBody body(0, geometry::MotionConfig{}, Vec3::Zero());
  EXPECT_THROW(PowerNumber{rotor_options(body)}, std::invalid_argument);
}

}  // namespace
}  // namespace partimix::analysis
