// The next sample, frame or checkpoint time comes in one step whatever the interval (issue 15:
// an interval of 1e-20 s stalled the run loop adding it to a time of order 1).
#include <gtest/gtest.h>

#include "app/run_state.hpp"

namespace partimix::app {
namespace {

TEST(NextMultiple, IsTheFirstMultiplePastTheTime) {
  EXPECT_DOUBLE_EQ(next_multiple(0.1, 0.25, 1e-12), 0.3);
  EXPECT_DOUBLE_EQ(next_multiple(0.1, 0.0, 1e-12), 0.1);
  EXPECT_DOUBLE_EQ(next_multiple(0.5, 0.1, 1e-12), 0.5);
}

TEST(NextMultiple, ATimeWithinTheToleranceOfAMultipleCountsAsIt) {
  EXPECT_NEAR(next_multiple(0.1, 0.3 - 1e-13, 1e-12), 0.4, 1e-15);
}

TEST(NextMultiple, ATinyIntervalStillGivesALaterTime) {
  const double next = next_multiple(1e-20, 0.1, 1e-10);
  EXPECT_GT(next, 0.1);
  EXPECT_LT(next, 0.1 + 1e-9);
}

}  // namespace
}  // namespace partimix::app
