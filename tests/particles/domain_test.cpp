// Domain::wrap moves a position by whole periods in one step, so that a position far out (or
// not finite, after a blow-up) costs no more than one near the box and never hangs the run.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "particles/domain.hpp"

namespace partimix {
namespace {

Domain periodic_x() {
  Domain domain;
  domain.lo = Vec3(-1.0, 0.0, 0.0);
  domain.hi = Vec3(2.0, 1.0, 1.0);
  domain.periodic = {true, false, false};
  return domain;
}

TEST(DomainWrap, MovesByWholePeriodsIntoTheBox) {
  const Domain domain = periodic_x();
  Vec3 x(2.5, 0.5, 0.5);
  domain.wrap(x);
  EXPECT_DOUBLE_EQ(x[0], -0.5);
  x = Vec3(-1.0 - 3.0 * 7 - 0.25, 0.5, 0.5);
  domain.wrap(x);
  EXPECT_NEAR(x[0], 1.75, 1e-12);
}

TEST(DomainWrap, TheUpperBoundIsTheLowerOne) {
  const Domain domain = periodic_x();
  Vec3 x(2.0, 0.5, 0.5);
  domain.wrap(x);
  EXPECT_EQ(x[0], -1.0);
  x = Vec3(-1.0 - 1e-17, 0.5, 0.5);
  domain.wrap(x);
  EXPECT_GE(x[0], -1.0);
  EXPECT_LT(x[0], 2.0);
}

TEST(DomainWrap, AHugeCoordinateLandsInTheBox) {
  const Domain domain = periodic_x();
  for (const double far : {1e300, -1e300, 1e17, -std::numeric_limits<double>::max()}) {
    Vec3 x(far, 0.5, 0.5);
    domain.wrap(x);
    EXPECT_GE(x[0], -1.0) << far;
    EXPECT_LT(x[0], 2.0) << far;
  }
}

TEST(DomainWrap, ANonFiniteCoordinateIsLeftForTheHealthCheck) {
  const Domain domain = periodic_x();
  Vec3 x(std::numeric_limits<double>::infinity(), 0.5, 0.5);
  domain.wrap(x);
  EXPECT_TRUE(std::isinf(x[0]));
  x[0] = std::numeric_limits<double>::quiet_NaN();
  domain.wrap(x);
  EXPECT_TRUE(std::isnan(x[0]));
}

TEST(DomainWrap, NonPeriodicAxesAreNotTouched) {
  const Domain domain = periodic_x();
  Vec3 x(0.0, 5.0, -3.0);
  domain.wrap(x);
  EXPECT_EQ(x, Vec3(0.0, 5.0, -3.0));
}

}  // namespace
}  // namespace partimix
