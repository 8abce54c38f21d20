// The analyses packing_fraction, velocity_profile and angle_of_repose (docs/case-reference.md,
// "analyses"): they load with their values and defaults (recorded in the resolved case), and bad
// ones are InputErrors naming file, line, column and key path.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "case_files.hpp"

namespace partimix::case_test {
namespace {

using ::testing::HasSubstr;

// kMinimal2D (17 lines), then the analyses list `items`: the first item is line 19.
std::string with_items(const std::string& items) {
  return kMinimal2D + "analyses:\n" + items;
}
constexpr int kFirstItem = 19;

const io::AnalysisSpec& only_analysis(const io::Case& loaded) {
  EXPECT_EQ(loaded.analyses.size(), 1u);
  return loaded.analyses.at(0);
}

TEST(CaseBedAnalyses, PackingFractionBox) {
  const io::Case loaded =
      load_text(with_items("  - {type: packing_fraction, min: [0.1, 0], max: [0.5, 0.4]}\n"));
  const io::AnalysisSpec& spec = only_analysis(loaded);
  EXPECT_EQ(spec.type, "packing_fraction");
  EXPECT_EQ(spec.packing.lo, Vec3(0.1, 0.0, 0.0));
  EXPECT_EQ(spec.packing.hi, Vec3(0.5, 0.4, 0.0));
  EXPECT_EQ(loaded.resolved["analyses"][0]["max"], nlohmann::json::parse("[0.5, 0.4]"));
}

TEST(CaseBedAnalyses, PackingFractionMaxMustExceedMin) {
  const InputError error =
      load_error(with_items("  - type: packing_fraction\n    min: [0, 0]\n    max: [0.5, 0]\n"));
  expect_location(error, "case.yaml", kFirstItem + 2, 10, "analyses[0].max");
  EXPECT_THAT(error.message(), HasSubstr("max must exceed min"));
}

TEST(CaseBedAnalyses, PackingFractionNeedsItsBox) {
  const InputError error = load_error(with_items("  - type: packing_fraction\n    min: [0, 0]\n"));
  EXPECT_EQ(error.location().key_path, "analyses[0].max") << error.what();
  EXPECT_THAT(error.message(), HasSubstr("missing required key 'max'"));
}

TEST(CaseBedAnalyses, VelocityProfileDefaults) {
  // bins 10, the speed.
  const io::Case loaded = load_text(
      with_items("  - {type: velocity_profile, start: [0.1, 0], end: [0.1, 1], width: 0.05}\n"));
  const analysis::ProfileLine& line = only_analysis(loaded).profile;
  EXPECT_EQ(line.start, Vec3(0.1, 0.0, 0.0));
  EXPECT_EQ(line.end, Vec3(0.1, 1.0, 0.0));
  EXPECT_EQ(line.bins, 10);
  EXPECT_DOUBLE_EQ(line.width, 0.05);
  EXPECT_TRUE(line.speed);
  const auto& resolved = loaded.resolved["analyses"][0];
  EXPECT_EQ(resolved["bins"], 10);
  EXPECT_EQ(resolved["component"], "speed");
}

TEST(CaseBedAnalyses, VelocityProfileComponentIsADirection) {
  const io::Case loaded =
      load_text(with_items("  - {type: velocity_profile, start: [0.1, 0], end: [0.1, 1], width: "
                           "0.05, bins: 4, component: [2, 0]}\n"));
  const analysis::ProfileLine& line = only_analysis(loaded).profile;
  EXPECT_FALSE(line.speed);
  EXPECT_EQ(line.direction, Vec3(1.0, 0.0, 0.0));  // normalised
  EXPECT_EQ(line.bins, 4);
  EXPECT_EQ(loaded.resolved["analyses"][0]["component"], nlohmann::json::parse("[2.0, 0.0]"));
  const io::Case speed =
      load_text(with_items("  - {type: velocity_profile, start: [0.1, 0], end: [0.1, 1], width: "
                           "0.05, component: speed}\n"));
  EXPECT_TRUE(only_analysis(speed).profile.speed);
}

TEST(CaseBedAnalyses, VelocityProfileBadComponents) {
  for (const char* component : {"fast", "[0, 0]", "[1, 0, 0]", "{x: 1}"}) {
    const InputError error = load_error(
        with_items(std::string("  - type: velocity_profile\n    start: [0, 0]\n    end: [0, 1]\n"
                               "    width: 0.1\n    component: ") +
                   component + "\n"));
    expect_location(error, "case.yaml", kFirstItem + 4, 16, "analyses[0].component");
    EXPECT_THAT(error.message(),
                HasSubstr("expected the word speed or a direction (a list of 2 numbers"))
        << component;
  }
}

TEST(CaseBedAnalyses, VelocityProfileBadLines) {
  const std::string head = "  - type: velocity_profile\n    start: [0, 0]\n";
  const InputError same = load_error(with_items(head + "    end: [0, 0]\n    width: 0.1\n"));
  expect_location(same, "case.yaml", kFirstItem + 2, 10, "analyses[0].end");
  EXPECT_THAT(same.message(), HasSubstr("end must differ from start"));
  const InputError no_width = load_error(with_items(head + "    end: [0, 1]\n"));
  EXPECT_EQ(no_width.location().key_path, "analyses[0].width") << no_width.what();
  const InputError zero_width = load_error(with_items(head + "    end: [0, 1]\n    width: 0\n"));
  expect_location(zero_width, "case.yaml", kFirstItem + 3, 12, "analyses[0].width");
  const InputError no_bins =
      load_error(with_items(head + "    end: [0, 1]\n    width: 0.1\n    bins: 0\n"));
  expect_location(no_bins, "case.yaml", kFirstItem + 4, 11, "analyses[0].bins");
  const InputError many_bins =
      load_error(with_items(head + "    end: [0, 1]\n    width: 0.1\n    bins: 1001\n"));
  expect_location(many_bins, "case.yaml", kFirstItem + 4, 11, "analyses[0].bins");
  EXPECT_THAT(many_bins.message(), HasSubstr("at most 1000 bins"));
}

TEST(CaseBedAnalyses, AngleOfReposeDefaultsIn2D) {
  // The axis is z (the plane's normal), gravity -y, 20 bins, trim 0.2.
  const io::Case loaded = load_text(with_items("  - {type: angle_of_repose}\n"));
  const analysis::ReposeSection& section = only_analysis(loaded).repose;
  EXPECT_EQ(section.axis, Vec3::UnitZ());
  EXPECT_EQ(section.centre, Vec3::Zero());
  EXPECT_EQ(section.down, Vec3(0.0, -1.0, 0.0));
  EXPECT_EQ(section.bins, 20);
  EXPECT_DOUBLE_EQ(section.trim, 0.2);
  const auto& resolved = loaded.resolved["analyses"][0];
  EXPECT_EQ(resolved["down"], nlohmann::json::parse("[0.0, -1.0]"));
  EXPECT_EQ(resolved["bins"], 20);
  EXPECT_EQ(resolved["trim"], 0.2);
  EXPECT_FALSE(resolved.contains("axis"));
}

TEST(CaseBedAnalyses, AngleOfReposeTakesNoAxisIn2D) {
  const InputError error = load_error(with_items("  - type: angle_of_repose\n    axis: [1, 0]\n"));
  expect_location(error, "case.yaml", kFirstItem + 1, 5, "analyses[0].axis");
  EXPECT_THAT(error.message(), HasSubstr("unknown key 'axis'"));
}

TEST(CaseBedAnalyses, AngleOfReposeIn3D) {
  const io::Case loaded = load_text(
      with_analyses_3d("  - {type: angle_of_repose, axis: [1, 0, 0], centre: [0, 0.5, 0.5], down: "
                       "[0, 0, -9.81], bins: 30, trim: 0.1}\n"));
  const analysis::ReposeSection& section = only_analysis(loaded).repose;
  EXPECT_EQ(section.axis, Vec3::UnitX());
  EXPECT_EQ(section.centre, Vec3(0.0, 0.5, 0.5));
  EXPECT_EQ(section.down, Vec3(0.0, 0.0, -9.81));
  EXPECT_EQ(section.bins, 30);
  EXPECT_DOUBLE_EQ(section.trim, 0.1);
}

TEST(CaseBedAnalyses, AngleOfReposeBadValues) {
  const InputError parallel = load_error(
      with_analyses_3d("  - type: angle_of_repose\n    axis: [0, 1, 0]\n    down: [0, -2, 0]\n"));
  expect_location(parallel, "case.yaml", kFirstAnalysis3D + 2, 11, "analyses[0].down");
  EXPECT_THAT(parallel.message(), HasSubstr("must not be zero or parallel to the axis"));
  const InputError zero_axis =
      load_error(with_analyses_3d("  - type: angle_of_repose\n    axis: [0, 0, 0]\n"));
  expect_location(zero_axis, "case.yaml", kFirstAnalysis3D + 1, 11, "analyses[0].axis");
  const InputError trim = load_error(with_items("  - type: angle_of_repose\n    trim: 0.5\n"));
  expect_location(trim, "case.yaml", kFirstItem + 1, 11, "analyses[0].trim");
  EXPECT_THAT(trim.message(), HasSubstr("trim must be below 0.5"));
  const InputError negative = load_error(with_items("  - type: angle_of_repose\n    trim: -0.1\n"));
  expect_location(negative, "case.yaml", kFirstItem + 1, 11, "analyses[0].trim");
  const InputError bins = load_error(with_items("  - type: angle_of_repose\n    bins: 1\n"));
  expect_location(bins, "case.yaml", kFirstItem + 1, 11, "analyses[0].bins");
}

TEST(CaseBedAnalyses, KeysOfOtherAnalysesAreUnknown) {
  const InputError error = load_error(
      with_items("  - type: packing_fraction\n    min: [0, 0]\n    max: [1, 1]\n    width: 0.1\n"));
  expect_location(error, "case.yaml", kFirstItem + 3, 5, "analyses[0].width");
  EXPECT_THAT(error.message(), HasSubstr("unknown key 'width'"));
}

}  // namespace
}  // namespace partimix::case_test
