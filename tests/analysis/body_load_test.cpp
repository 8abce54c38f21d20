// Loads on bodies (docs/power.md; the seed's eq. 23): force, torques about two points with the
// particles' couples, and the power the body gives the fluid, worked out by hand on a
// hand-built store; the fields the measurement needs; and the body_loads analysis: its columns,
// a sample of a rotor and of a planetary body whose own axis has moved, and its summary.
#include "analysis/body_load.hpp"

#include <gtest/gtest.h>

#include <map>
#include <string>
#include <vector>

#include "analysis/body_loads.hpp"
#include "core/error.hpp"
#include "load_fixtures.hpp"

namespace partimix::analysis {
namespace {

using analysis_test::kPi;
using analysis_test::kRotorAxis;
using analysis_test::kRotorRpm;
using analysis_test::kRotorVessel;
using analysis_test::LoadedStore;
using analysis_test::MovingBody;
using analysis_test::RotorStore;
using analysis_test::sample_once;

constexpr double kTight = 1e-12;

void expect_near(const Vec3& actual, const Vec3& expected) {
  EXPECT_NEAR((actual - expected).norm(), 0.0, kTight) << actual.transpose();
}

// Body 0: particle a at (1, 0, 0) with force (0, 2, 0), couple (0, 0, 0.5), velocity (0, 3, 0);
// particle b at (-1, 0, 0) with force (0, -2, 1), couple (0, 0, 0.25), velocity (0, -3, 0).
// A fluid particle and a particle of body 1 carry large loads that must not count.
class TwoBodies : public LoadedStore {
 public:
  TwoBodies() {
    add(-1, {Vec3(0, 5, 0), Vec3(1, 1, 1), Vec3(50, 50, 50), Vec3(9, 9, 9)});
    add(0, {Vec3(1, 0, 0), Vec3(0, 3, 0), Vec3(0, 2, 0), Vec3(0, 0, 0.5)});
    add(1, {Vec3(0, 0, 3), Vec3(0, 0, 4), Vec3(100, 100, 100), Vec3(1, 2, 3)});
    add(0, {Vec3(-1, 0, 0), Vec3(0, -3, 0), Vec3(0, -2, 1), Vec3(0, 0, 0.25)});
  }
};

TEST(BodyLoad, ForceIsTheSumOverTheBodysParticles) {
  // (0, 2, 0) + (0, -2, 1) = (0, 0, 1).
  const TwoBodies store;
  expect_near(measure_body_load(store.store(), 0, Vec3::Zero(), Vec3::Zero()).force, Vec3(0, 0, 1));
}

TEST(BodyLoad, TorquesAboutTwoPointsIncludeTheCouples) {
  // About the origin: (1, 0, 0) x (0, 2, 0) = (0, 0, 2); (-1, 0, 0) x (0, -2, 1) = (0, 1, 2);
  // couples (0, 0, 0.75): Gamma = (0, 1, 4.75).
  // About (0, 1, 0): (1, -1, 0) x (0, 2, 0) = (0, 0, 2); (-1, -1, 0) x (0, -2, 1) = (-1, 1, 2);
  // with the couples (-1, 1, 4.75) = (0, 1, 4.75) - (0, 1, 0) x F.
  const TwoBodies store;
  const BodyLoad load = measure_body_load(store.store(), 0, Vec3::Zero(), Vec3(0, 1, 0));
  expect_near(load.torque_own, Vec3(0, 1, 4.75));
  expect_near(load.torque_vessel, Vec3(-1, 1, 4.75));
  // The same points swapped swap the torques.
  const BodyLoad swapped = measure_body_load(store.store(), 0, Vec3(0, 1, 0), Vec3::Zero());
  expect_near(swapped.torque_own, Vec3(-1, 1, 4.75));
  expect_near(swapped.torque_vessel, Vec3(0, 1, 4.75));
}

TEST(BodyLoad, OtherBodiesAndTheFluidAreLeftOut) {
  // Body 1 alone: F = (100, 100, 100); about the origin (0, 0, 3) x (100, 100, 100) =
  // (0 100 - 3 100, 3 100 - 0 100, 0) = (-300, 300, 0), plus the couple (1, 2, 3).
  const TwoBodies store;
  const BodyLoad load = measure_body_load(store.store(), 1, Vec3::Zero(), Vec3::Zero());
  expect_near(load.force, Vec3(100, 100, 100));
  expect_near(load.torque_own, Vec3(-299, 302, 3));
  // A body with no particles has no load.
  const BodyLoad none = measure_body_load(store.store(), 2, Vec3::Zero(), Vec3::Zero());
  expect_near(none.force, Vec3::Zero());
  expect_near(none.torque_own, Vec3::Zero());
}

TEST(BodyLoad, MissingFieldsAreARunError) {
  ParticleStore store;
  store.resize(2);
  EXPECT_THROW(measure_body_load(store, 0, Vec3::Zero(), Vec3::Zero()), RunError);
  store.add_integer("body", "");
  EXPECT_THROW(measure_body_load(store, 0, Vec3::Zero(), Vec3::Zero()), RunError);
  store.add_vector("body_force", "N");
  EXPECT_THROW(measure_body_load(store, 0, Vec3::Zero(), Vec3::Zero()), RunError);
  store.add_vector("body_couple", "N m");
  EXPECT_NO_THROW(measure_body_load(store, 0, Vec3::Zero(), Vec3::Zero()));
}

TEST(BodyLoadsAnalysis, ColumnsArePrefixedWithTheBodyAndCarryUnits) {
  const MovingBody body(1, analysis_test::rotation(Vec3::Zero(), 30.0), Vec3::Zero());
  const BodyLoads analysis(body.options);
  const std::vector<Column> columns = analysis.columns();
  const std::vector<std::pair<std::string, std::string>> expected{
      {"body1_force_x", "N"},       {"body1_force_y", "N"},         {"body1_force_z", "N"},
      {"body1_torque_own", "N m"},  {"body1_torque_vessel", "N m"}, {"body1_power", "W"},
      {"body1_power_rotation", "W"}};
  ASSERT_EQ(columns.size(), expected.size());
  for (std::size_t k = 0; k < expected.size(); ++k) {
    EXPECT_EQ(columns[k].name, expected[k].first);
    EXPECT_EQ(columns[k].unit, expected[k].second) << expected[k].first;
  }
  EXPECT_TRUE(analysis.needs_body_forces());
}

TEST(BodyLoadsAnalysis, SampleOfTheRotor) {
  // The rotor of load_fixtures.hpp: F = (0, 1, 0), Gamma_own = -0.17, Gamma_vessel = 0.03,
  // power = power_rotation = 0.68 pi (a pure rotation about the own axis: -omega . Gamma_own).
  const MovingBody body(0, analysis_test::rotation(kRotorAxis, kRotorRpm), kRotorVessel);
  BodyLoads analysis(body.options);
  const std::vector<double> values = sample_once(analysis, RotorStore(1.0).store(), 0.2);
  const std::vector<double> expected{0.0, 1.0, 0.0, -0.17, 0.03, 0.68 * kPi, 0.68 * kPi};
  ASSERT_EQ(values.size(), expected.size());
  for (std::size_t k = 0; k < expected.size(); ++k)
    EXPECT_NEAR(values[k], expected[k], 1e-12) << "column " << k;
}

TEST(BodyLoadsAnalysis, PlanetaryTorqueOwnIsAboutTheOwnAxisWhereItIsNow) {
  // Own axis through (0.1, 0, 0) at t = 0, revolving at 15 rpm about the origin: at t = 1 s it
  // has turned a quarter revolution to (0, 0.1, 0). Spin 60 rpm: omega_R = 2 pi rad/s.
  // Particle a at (0.05, 0.1) with force (1, 0, 0); particle b at (0, 0.15) with (-2, 0, 0).
  //   own axis (0, 0.1):  a: (0.05, 0) x (1, 0) = 0;          b: (0, 0.05) x (-2, 0) = 0.1
  //   vessel (0, 0):      a: (0.05, 0.1) x (1, 0) = -0.1;     b: (0, 0.15) x (-2, 0) = 0.3
  // so torque_own = 0.1 and torque_vessel = 0.2 (= 0.1 + (0, 0.1) x F, F = (-1, 0)); about the
  // own axis's place at t = 0, (0.1, 0), torque_own would read -0.1 + 0.1 = 0.
  // power_rotation = |2 pi 0.1| = 0.2 pi; power -(F . v_o + omega_R Gamma_own) with the own
  // axis moving at v_o = (pi/2) z x (0, 0.1) = (-0.05 pi, 0): -(0.05 pi + 0.2 pi) = -0.25 pi.
  const MovingBody body(3, analysis_test::planetary(Vec3(0.1, 0, 0), Vec3::Zero(), 60.0, 15.0),
                        Vec3::Zero());
  LoadedStore store;
  store.add(3, {Vec3(0.05, 0.1, 0), Vec3::Zero(), Vec3(1, 0, 0), Vec3::Zero()});
  store.add(3, {Vec3(0, 0.15, 0), Vec3::Zero(), Vec3(-2, 0, 0), Vec3::Zero()});
  BodyLoads analysis(body.options);
  const std::vector<double> values = sample_once(analysis, store.store(), 1.0);
  EXPECT_NEAR(values[0], -1.0, 1e-12);
  EXPECT_NEAR(values[3], 0.1, 1e-12);
  EXPECT_NEAR(values[4], 0.2, 1e-12);
  EXPECT_NEAR(values[5], -0.25 * kPi, 1e-12);
  EXPECT_NEAR(values[6], 0.2 * kPi, 1e-12);
}

TEST(BodyLoadsAnalysis, FiguresAreMeansOverTheLastRevolution) {
  // torque_own: A = -0.17, B = -0.34; (A + 3 B)/4 = (-0.17 - 1.02)/4 = -0.2975 N m.
  // force_y: A = 1, B = 2; (1 + 6)/4 = 1.75 N.
  const MovingBody body(0, analysis_test::rotation(kRotorAxis, kRotorRpm), kRotorVessel);
  BodyLoads analysis(body.options);
  analysis_test::sample_step_history(analysis, RotorStore(1.0).store(), RotorStore(2.0).store());
  Figures figures;
  analysis.add_figures(figures);
  EXPECT_NEAR(figures.at("body0_torque_own"), -0.2975, 1e-12);
  EXPECT_NEAR(figures.at("body0_force_y"), 1.75, 1e-12);
  EXPECT_DOUBLE_EQ(figures.at("body0_average_from"), 0.5);
  EXPECT_DOUBLE_EQ(figures.at("body0_average_to"), 1.0);
  EXPECT_DOUBLE_EQ(figures.at("body0_average_revolutions"), 1.0);
  EXPECT_EQ(figures.size(), 7u + 3u);
}

TEST(BodyLoadsAnalysis, FiguresOfAFixedBodyAreTheLastSample) {
  // A fixed body has no period: the figures are the values at t = 1 (loads doubled), the window
  // [1, 1] and 0 revolutions. force_y = 2; torque_own about the origin (the default axis
  // point): 0.55 (-2) + 0.45 (4) - 0.02 2 = 0.66 N m.
  const MovingBody body(0, geometry::MotionConfig{}, Vec3::Zero());
  BodyLoads analysis(body.options);
  analysis_test::sample_step_history(analysis, RotorStore(1.0).store(), RotorStore(2.0).store());
  Figures figures;
  analysis.add_figures(figures);
  EXPECT_NEAR(figures.at("body0_force_y"), 2.0, 1e-12);
  EXPECT_NEAR(figures.at("body0_torque_own"), 0.66, 1e-12);
  EXPECT_DOUBLE_EQ(figures.at("body0_average_from"), 1.0);
  EXPECT_DOUBLE_EQ(figures.at("body0_average_to"), 1.0);
  EXPECT_DOUBLE_EQ(figures.at("body0_average_revolutions"), 0.0);
}

TEST(BodyLoadsAnalysis, NoSamplesNoFigures) {
  const MovingBody body(0, analysis_test::rotation(kRotorAxis, kRotorRpm), kRotorVessel);
  const BodyLoads analysis(body.options);
  Figures figures;
  analysis.add_figures(figures);
  EXPECT_TRUE(figures.empty());
}

}  // namespace
}  // namespace partimix::analysis
