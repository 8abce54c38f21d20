// The run clock's step towards the end of a run (app/run_clock.hpp): the adaptive step while
// more than two remain, then the rest split so that no step is shorter than half the one
// before, and the end reached exactly.
#include <gtest/gtest.h>

#include "app/run_clock.hpp"

namespace partimix::app {
namespace {

TEST(StepTowardsEnd, TakesTheFullStepWhileTwoOrMoreRemain) {
  EXPECT_EQ(step_towards_end(1.0, 10.0), 1.0);
  EXPECT_EQ(step_towards_end(1.0, 2.0), 1.0);
}

TEST(StepTowardsEnd, SplitsWhatRemainsBetweenOneAndTwoSteps) {
  EXPECT_DOUBLE_EQ(step_towards_end(1.0, 1.01), 0.505);
  EXPECT_DOUBLE_EQ(step_towards_end(1.0, 1.9), 0.95);
}

TEST(StepTowardsEnd, TakesTheRestWhenLessThanAStepRemains) {
  EXPECT_EQ(step_towards_end(1.0, 0.3), 0.3);
  EXPECT_EQ(step_towards_end(1.0, 1.0), 1.0);
}

TEST(StepTowardsEnd, NoStepIsShorterThanHalfTheOneBefore) {
  // From 1.01 steps before the end: 0.505 and 0.505, where min(step, remaining) gave 1 and 0.01.
  double remaining = 7.01;
  double previous = 1.0;
  int steps = 0;
  while (remaining > 0.0 && steps < 100) {
    const double dt = step_towards_end(1.0, remaining);
    EXPECT_GE(dt, 0.5 * previous - 1e-12);
    previous = dt;
    remaining -= dt;
    ++steps;
  }
  EXPECT_NEAR(remaining, 0.0, 1e-12);
  EXPECT_EQ(steps, 8);
}

}  // namespace
}  // namespace partimix::app
