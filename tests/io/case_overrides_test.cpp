// --set overrides change the YAML tree before validation; their errors point at "--set".
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "case_files.hpp"
#include "support/sph_case.hpp"

namespace partimix::case_test {
namespace {

using ::testing::HasSubstr;

TEST(CaseOverrides, SetChangesAValue) {
  const io::Case loaded = load_text(kMinimal2D, {"sph.spacing=0.02"});
  EXPECT_DOUBLE_EQ(test_support::sph_config(loaded).spacing, 0.02);
  EXPECT_EQ(loaded.resolved["sph"]["spacing"], 0.02);
}

TEST(CaseOverrides, LaterSetsWin) {
  const io::Case loaded = load_text(kMinimal2D, {"time.end=2", "time.end=3"});
  EXPECT_DOUBLE_EQ(loaded.time.end, 3.0);
}

TEST(CaseOverrides, SetCreatesMissingMaps) {
  const io::Case loaded = load_text(kMinimal2D, {"sph.density.delta=0.2", "output.frames=false"});
  EXPECT_DOUBLE_EQ(test_support::sph_config(loaded).density.delta, 0.2);
  EXPECT_FALSE(loaded.output.frames);
}

TEST(CaseOverrides, ValueIsParsedAsYaml) {
  const io::Case loaded = load_text(kMinimal2D, {"domain.periodic=[x]", "gravity=[0, -9.81]"});
  EXPECT_TRUE(loaded.domain.periodic[0]);
  EXPECT_EQ(loaded.gravity, Vec3(0.0, -9.81, 0.0));
}

TEST(CaseOverrides, ListIndexSetsAnItemKey) {
  const io::Case loaded = load_text(kMinimal2D, {"fluid.regions[0].max=[1,2]"});
  EXPECT_EQ(test_support::fluid_of(loaded).regions[0].shape->upper(), Vec3(1.0, 2.0, 1.0));
}

TEST(CaseOverrides, IndexJustPastTheEndAppends) {
  const io::Case loaded =
      load_text(kMinimal2D, {"fluid.regions[1]={shape: box, min: [1, 0], max: [1.5, 0.5]}"});
  ASSERT_EQ(test_support::fluid_of(loaded).regions.size(), 2u);
  EXPECT_EQ(test_support::fluid_of(loaded).regions[1].shape->lower(), Vec3(1.0, 0.0, -1.0));
}

TEST(CaseOverrides, UnknownKeyIsNamed) {
  const InputError error = load_error(kMinimal2D, {"sph.kernal=cubic_spline"});
  expect_location(error, "--set", 0, 0, "sph.kernal");
  EXPECT_THAT(error.message(), HasSubstr("unknown key 'kernal'; expected one of: spacing"));
}

TEST(CaseOverrides, UnknownSectionIsNamed) {
  const InputError error = load_error(kMinimal2D, {"sphh.spacing=0.1"});
  expect_location(error, "--set", 0, 0, "sphh");
  EXPECT_THAT(error.message(), HasSubstr("unknown key 'sphh'"));
}

TEST(CaseOverrides, BadValuePointsAtSet) {
  const InputError error = load_error(kMinimal2D, {"sph.spacing=abc"});
  expect_location(error, "--set", 0, 0, "sph.spacing");
  EXPECT_EQ(error.message(), "expected a number, got 'abc'");
}

TEST(CaseOverrides, ErrorInsideASetMapPointsAtSet) {
  const InputError error = load_error(kMinimal2D, {"fluid.regions[0]={shape: box, min: [0, 0]}"});
  expect_location(error, "--set", 0, 0, "fluid.regions[0].max");
  EXPECT_EQ(error.message(), "missing required key 'max'");
}

TEST(CaseOverrides, ErrorsElsewhereStillPointAtTheFile) {
  const InputError error =
      load_error(replace_line(kMinimal2D, 10, "  spacing: -1"), {"time.end=2"});
  expect_location(error, "case.yaml", 10, 12, "sph.spacing");
}

TEST(CaseOverrides, SetWithoutEqualsIsAnError) {
  const InputError error = load_error(kMinimal2D, {"sph.spacing"});
  expect_location(error, "--set", 0, 0, "sph.spacing");
  EXPECT_THAT(error.message(), HasSubstr("expected key.path=value"));
}

TEST(CaseOverrides, SetWithAnEmptyPathIsAnError) {
  const InputError error = load_error(kMinimal2D, {"=0.1"});
  expect_location(error, "--set", 0, 0, "");
  EXPECT_THAT(error.message(), HasSubstr("empty key path"));
}

TEST(CaseOverrides, SetWithAnEmptyKeyIsAnError) {
  const InputError error = load_error(kMinimal2D, {"sph..spacing=0.1"});
  expect_location(error, "--set", 0, 0, "sph..spacing");
  EXPECT_THAT(error.message(), HasSubstr("empty key"));
}

TEST(CaseOverrides, MalformedIndexIsAnError) {
  const InputError error = load_error(kMinimal2D, {"fluid.regions[a].max=[1,2]"});
  EXPECT_EQ(error.location().file, "--set");
  EXPECT_THAT(error.message(), HasSubstr("malformed list index"));
}

TEST(CaseOverrides, IndexOutOfRangeIsAnError) {
  const InputError error = load_error(kMinimal2D, {"fluid.regions[5].max=[1,2]"});
  expect_location(error, "--set", 0, 0, "fluid.regions[5]");
  EXPECT_EQ(error.message(),
            "list index out of range; 'fluid.regions' allows 0 to 1 (1 appends an item)");
}

TEST(CaseOverrides, KeyThroughANumberIsAnError) {
  const InputError error = load_error(kMinimal2D, {"sph.spacing.x=1"});
  expect_location(error, "--set", 0, 0, "sph.spacing.x");
  EXPECT_EQ(error.message(), "'sph.spacing' is not a map");
}

TEST(CaseOverrides, MalformedValueIsAnError) {
  const InputError error = load_error(kMinimal2D, {"domain.max=[1, 2"});
  expect_location(error, "--set", 0, 0, "domain.max");
  EXPECT_THAT(error.message(), HasSubstr("cannot parse the value '[1, 2'"));
}

TEST(CaseOverrides, IndexTooLargeForANumberIsAnError) {
  const InputError error =
      load_error(kMinimal2D, {"fluid.regions[99999999999999999999].max=[1,2]"});
  EXPECT_EQ(error.location().file, "--set");
  EXPECT_THAT(error.message(), HasSubstr("list index [99999999999999999999] is too large"));
}

TEST(CaseOverrides, NullRemovesAKeySoAnotherCanTakeItsPlace) {
  const io::Case loaded =
      load_text(kMinimal2D, {"fluid.viscosity=null",
                             "fluid.rheology={model: power_law, consistency: 0.1, "
                             "flow_index: 1.5, viscosity_max: 10}"});
  EXPECT_FALSE(loaded.resolved["fluid"].contains("viscosity"));
  EXPECT_EQ(loaded.resolved["fluid"]["rheology"]["model"], "power_law");
}

TEST(CaseOverrides, NullOfAMissingKeyIsNoError) {
  const io::Case loaded = load_text(kMinimal2D, {"sph.density.delta=~", "nothing.here="});
  EXPECT_DOUBLE_EQ(loaded.time.end, 1.0);
}

TEST(CaseOverrides, NullOfAListItemIsAnError) {
  const InputError error = load_error(kMinimal2D, {"fluid.regions[0]=null"});
  EXPECT_THAT(error.message(), HasSubstr("null removes a key of a map"));
}

}  // namespace
}  // namespace partimix::case_test
