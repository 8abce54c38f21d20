// The runs of `partimix sweep`: reading --vary KEY=v1,v2,... and the cartesian product.
#include "app/sweep_plan.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/error.hpp"

namespace partimix::app {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;

TEST(SweepPlan, SplitsValuesAtCommasOutsideBrackets) {
  const std::vector<SweepAxis> axes =
      parse_sweep_axes({"fluid.viscosity=1e-3, 2e-3", "gravity=[0,-9.81],[0,-4.9]",
                        "fluid.regions[1]={shape: box, min: [0, 0]}"});
  ASSERT_EQ(axes.size(), 3u);
  EXPECT_EQ(axes[0].key, "fluid.viscosity");
  EXPECT_THAT(axes[0].values, ElementsAre("1e-3", "2e-3"));
  EXPECT_EQ(axes[1].key, "gravity");
  EXPECT_THAT(axes[1].values, ElementsAre("[0,-9.81]", "[0,-4.9]"));
  EXPECT_EQ(axes[2].key, "fluid.regions[1]");
  EXPECT_THAT(axes[2].values, ElementsAre("{shape: box, min: [0, 0]}"));
}

TEST(SweepPlan, PointsAreTheCartesianProductWithTheLastAxisFastest) {
  const std::vector<SweepAxis> axes{{"a", {"1", "2"}}, {"b", {"x", "y", "z"}}};
  const std::vector<SweepPoint> points = sweep_points(axes);
  EXPECT_THAT(points,
              ElementsAre(ElementsAre("1", "x"), ElementsAre("1", "y"), ElementsAre("1", "z"),
                          ElementsAre("2", "x"), ElementsAre("2", "y"), ElementsAre("2", "z")));
  EXPECT_THAT(point_overrides(axes, points[4]), ElementsAre("a=2", "b=y"));
}

struct BadVary {
  const char* name;
  std::string text;
  std::string message;  // part of the error
};

class BadSweepAxis : public ::testing::TestWithParam<BadVary> {};

TEST_P(BadSweepAxis, IsAnInputErrorNamingVaryAndTheKey) {
  try {
    parse_sweep_axes({"time.end=1,2", GetParam().text});
    FAIL() << "no error for " << GetParam().text;
  } catch (const InputError& error) {
    EXPECT_EQ(error.location().file, "--vary");
    EXPECT_THAT(error.what(), HasSubstr(GetParam().message));
  }
}

const BadVary kBadVaries[] = {
    {"NoEquals", "fluid.viscosity", "fluid.viscosity: expected KEY=v1,v2,... (no '=')"},
    {"NoValues", "fluid.viscosity=", "fluid.viscosity: no values"},
    {"EmptyValue", "fluid.viscosity=1,,2", "fluid.viscosity: empty value in '1,,2'"},
    {"EmptyKey", "=1,2", "empty key"},
    {"VariedTwice", "time.end=3", "time.end: varied twice"},
};

INSTANTIATE_TEST_SUITE_P(Texts, BadSweepAxis, ::testing::ValuesIn(kBadVaries),
                         [](const auto& variant) { return std::string(variant.param.name); });

}  // namespace
}  // namespace partimix::app
