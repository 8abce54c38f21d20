// Time averages of the summary (docs/power.md, "Summary"): the trapezoidal mean of a sampled
// signal over a window clipped to the samples, the window of the last k revolutions, the
// revolution period of each motion, and the figures a column history adds.
#include "analysis/time_average.hpp"

#include <gtest/gtest.h>

#include <initializer_list>
#include <map>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "analysis/averaging_window.hpp"

namespace partimix::analysis {
namespace {

constexpr double kTight = 1e-12;

SampledSignal signal_of(std::initializer_list<std::pair<double, double>> samples) {
  SampledSignal signal;
  for (const auto& [time, value] : samples)
    signal.add(time, value);
  return signal;
}

// v = 2 t + 1 at t = 0, 0.5, ..., 3.
SampledSignal linear() {
  SampledSignal signal;
  for (int k = 0; k <= 6; ++k)
    signal.add(0.5 * k, 2.0 * (0.5 * k) + 1.0);
  return signal;
}

TEST(SampledSignal, MeanOfALinearSignalIsItsValueAtTheWindowMidpoint) {
  // The trapezoidal rule is exact for a linear signal: mean over [a, b] = v((a + b)/2).
  const SampledSignal signal = linear();
  EXPECT_NEAR(signal.mean(1.0, 2.5), 2.0 * 1.75 + 1.0, kTight);  // window on samples: 4.5
  EXPECT_NEAR(signal.mean(0.2, 2.7), 2.0 * 1.45 + 1.0, kTight);  // between samples: 3.9
}

TEST(SampledSignal, StepLikeSignalByTheTrapezoidalRule) {
  // (0, 0), (1, 0), (2, 4), (3, 4): the ramp from t = 1 to 2 is linear between the samples.
  //   [0, 3]:   0 1 + (0 + 4)/2 1 + 4 1 = 6, mean 2
  //   [1.5, 3]: v(1.5) = 2; (2 + 4)/2 0.5 + 4 1 = 5.5, mean 5.5/1.5 = 11/3
  const SampledSignal signal = signal_of({{0, 0}, {1, 0}, {2, 4}, {3, 4}});
  EXPECT_NEAR(signal.mean(0.0, 3.0), 2.0, kTight);
  EXPECT_NEAR(signal.mean(1.5, 3.0), 11.0 / 3.0, kTight);
}

TEST(SampledSignal, UnevenSampleSpacing) {
  // (0, 1), (1, 3), (4, 0): (1 + 3)/2 1 + (3 + 0)/2 3 = 2 + 4.5 = 6.5 over 4 s: 1.625.
  EXPECT_NEAR(signal_of({{0, 1}, {1, 3}, {4, 0}}).mean(0.0, 4.0), 1.625, kTight);
}

TEST(SampledSignal, WindowIsClippedToTheSampledSpan) {
  const SampledSignal signal = signal_of({{0, 0}, {1, 0}, {2, 4}, {3, 4}});
  EXPECT_NEAR(signal.mean(-5.0, 10.0), 2.0, kTight);  // = mean over [0, 3]
  EXPECT_NEAR(signal.mean(2.5, 100.0), 4.0, kTight);  // = mean over [2.5, 3]
}

TEST(SampledSignal, SingleSampleOrEmptyWindowGivesTheLastValue) {
  EXPECT_DOUBLE_EQ(signal_of({{1.0, 7.0}}).mean(0.0, 5.0), 7.0);
  const SampledSignal signal = signal_of({{0, 0}, {1, 0}, {2, 4}, {3, 5}});
  EXPECT_DOUBLE_EQ(signal.mean(3.0, 3.0), 5.0);  // the window of a body that does not turn
  EXPECT_DOUBLE_EQ(signal.mean(7.0, 9.0), 5.0);  // after the last sample: clipped to nothing
  EXPECT_DOUBLE_EQ(signal.first_time(), 0.0);
  EXPECT_DOUBLE_EQ(signal.last_time(), 3.0);
  EXPECT_DOUBLE_EQ(signal.last_value(), 5.0);
}

TEST(SampledSignal, RepeatedSampleTimeAddsNothing) {
  // Two samples at t = 1 (a jump from 0 to 4): the zero-length interval contributes nothing;
  // [0, 2]: 0 1 + 4 1 = 4, mean 2.
  EXPECT_NEAR(signal_of({{0, 0}, {1, 0}, {1, 4}, {2, 4}}).mean(0.0, 2.0), 2.0, kTight);
}

TEST(AveragingWindow, LastRevolutionsBeforeTheLastSample) {
  // Period 2 s, samples over [0, 5]: one revolution is [3, 5], 1.5 revolutions [2, 5].
  const AveragingWindow one = averaging_window(0.0, 5.0, 2.0, 1.0);
  EXPECT_DOUBLE_EQ(one.from, 3.0);
  EXPECT_DOUBLE_EQ(one.to, 5.0);
  EXPECT_DOUBLE_EQ(one.revolutions, 1.0);
  const AveragingWindow more = averaging_window(0.0, 5.0, 2.0, 1.5);
  EXPECT_DOUBLE_EQ(more.from, 2.0);
  EXPECT_DOUBLE_EQ(more.revolutions, 1.5);
}

TEST(AveragingWindow, ShortRunsGiveFewerRevolutions) {
  // Samples over [0.5, 1.2], period 2 s: the window is all of it, 0.7/2 = 0.35 revolutions.
  const AveragingWindow window = averaging_window(0.5, 1.2, 2.0, 1.0);
  EXPECT_DOUBLE_EQ(window.from, 0.5);
  EXPECT_DOUBLE_EQ(window.to, 1.2);
  EXPECT_NEAR(window.revolutions, 0.35, kTight);
}

TEST(AveragingWindow, NoPeriodIsTheLastInstant) {
  const AveragingWindow window = averaging_window(0.0, 4.0, 0.0, 1.0);
  EXPECT_DOUBLE_EQ(window.from, 4.0);
  EXPECT_DOUBLE_EQ(window.to, 4.0);
  EXPECT_DOUBLE_EQ(window.revolutions, 0.0);
}

geometry::MotionConfig motion(const std::string& type, double rpm, double revolution_rpm = 0.0) {
  geometry::MotionConfig config;
  config.type = type;
  config.rpm = rpm;
  config.revolution_rpm = revolution_rpm;
  return config;
}

TEST(RevolutionPeriod, RotationIsSixtyOverRpm) {
  EXPECT_DOUBLE_EQ(revolution_period(motion("rotation", 30.0)), 2.0);
  EXPECT_DOUBLE_EQ(revolution_period(motion("rotation", -120.0)), 0.5);  // |rpm|
  EXPECT_DOUBLE_EQ(revolution_period(motion("rotation", 0.0)), 0.0);
}

TEST(RevolutionPeriod, PlanetaryIsTheRevolutionNotTheSpin) {
  // N_G = -25 rpm: 60/25 = 2.4 s, whatever the spin (60 rpm, 1 s).
  EXPECT_DOUBLE_EQ(revolution_period(motion("planetary", 60.0, -25.0)), 2.4);
  // No revolution: the spin is the only turning, 1 s.
  EXPECT_DOUBLE_EQ(revolution_period(motion("planetary", 60.0, 0.0)), 1.0);
}

TEST(RevolutionPeriod, FixedBodyHasNone) {
  EXPECT_DOUBLE_EQ(revolution_period(motion("fixed", 0.0)), 0.0);
  EXPECT_DOUBLE_EQ(revolution_period(geometry::MotionConfig{}), 0.0);
}

TEST(ColumnHistory, FiguresAreColumnMeansAndThePrefixedWindow) {
  // a = t, b = 10 at t = 0..4, period 2, one revolution: window [2, 4], mean a = 3, b = 10.
  ColumnHistory history({{"a", "m"}, {"b", ""}});
  for (int k = 0; k <= 4; ++k) {
    const std::vector<double> row{static_cast<double>(k), 10.0};
    history.add(k, row);
  }
  Figures figures;
  history.add_figures(figures, "p_", 2.0, 1.0);
  const std::map<std::string, double> expected{{"a", 3.0},
                                               {"b", 10.0},
                                               {"p_average_from", 2.0},
                                               {"p_average_to", 4.0},
                                               {"p_average_revolutions", 1.0}};
  ASSERT_EQ(figures.size(), expected.size());
  for (const auto& [name, value] : expected)
    EXPECT_NEAR(figures.at(name), value, kTight) << name;
  EXPECT_EQ(figures.unit("a"), "m");
  EXPECT_EQ(figures.unit("p_average_from"), "s");
}

TEST(ColumnHistory, AFullWindowAfterTheRampHasNoCaveat) {
  ColumnHistory history(std::vector<Column>{{"a", ""}});
  for (int k = 0; k <= 10; ++k) {
    const double value = 1.0;
    history.add(0.1 * k, std::span<const double>(&value, 1));
  }
  std::map<std::string, std::string> caveats;
  history.add_caveats(caveats, 0.5, 1.0, 0.2);
  EXPECT_TRUE(caveats.empty());
  history.add_caveats(caveats, 0.5, 1.0, 0.6);
  EXPECT_NE(caveats.at("a").find("takes in the start-up ramp"), std::string::npos);
  caveats.clear();
  history.add_caveats(caveats, 0.5, 3.0, 0.0);
  EXPECT_NE(caveats.at("a").find("2 of the 3 revolutions asked"), std::string::npos);
}

}  // namespace
}  // namespace partimix::analysis
