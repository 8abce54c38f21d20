// The analyses mass_in_region and height_profile (docs/case-reference.md, "analyses"): they load
// with their values and defaults (recorded in the resolved case), and bad ones are InputErrors
// naming file, line, column and key path.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <limits>
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

TEST(CaseDischargeAnalyses, MassInRegionLoads) {
  const io::Case loaded =
      load_text(with_items("  - {type: mass_in_region, region: {min: [0, 0.2], max: [0.5, 1]}, "
                           "fit_from: 0.1, fit_until: 0.8}\n"));
  const io::AnalysisSpec& spec = only_analysis(loaded);
  EXPECT_EQ(spec.type, "mass_in_region");
  EXPECT_EQ(spec.region_mass.lo, Vec3(0.0, 0.2, 0.0));
  EXPECT_EQ(spec.region_mass.hi, Vec3(0.5, 1.0, 0.0));
  EXPECT_DOUBLE_EQ(spec.region_mass.fit_from, 0.1);
  EXPECT_DOUBLE_EQ(spec.region_mass.fit_until, 0.8);
  const auto& resolved = loaded.resolved["analyses"][0];
  EXPECT_EQ(resolved["region"]["max"], nlohmann::json::parse("[0.5, 1.0]"));
  EXPECT_EQ(resolved["fit_until"], 0.8);
}

TEST(CaseDischargeAnalyses, MassInRegionFitsEverySampleByDefault) {
  const io::Case loaded =
      load_text(with_items("  - {type: mass_in_region, region: {min: [0, 0], max: [0.5, 1]}}\n"));
  const analysis::MassRegion& region = only_analysis(loaded).region_mass;
  EXPECT_EQ(region.fit_from, 0.0);
  EXPECT_EQ(region.fit_until, std::numeric_limits<double>::infinity());
  const auto& resolved = loaded.resolved["analyses"][0];
  EXPECT_EQ(resolved["fit_from"], 0.0);
  EXPECT_EQ(resolved["fit_until"], "auto");
}

TEST(CaseDischargeAnalyses, MassInRegionNeedsItsRegion) {
  const InputError missing = load_error(with_items("  - type: mass_in_region\n"));
  EXPECT_EQ(missing.location().key_path, "analyses[0].region") << missing.what();
  EXPECT_THAT(missing.message(), HasSubstr("missing required key 'region'"));
  const InputError word = load_error(with_items("  - type: mass_in_region\n    region: box\n"));
  expect_location(word, "case.yaml", kFirstItem + 1, 13, "analyses[0].region");
}

TEST(CaseDischargeAnalyses, MassInRegionBadBoxes) {
  const std::string head = "  - type: mass_in_region\n    region:\n      min: [0, 0]\n";
  const InputError flat = load_error(with_items(head + "      max: [0.5, 0]\n"));
  expect_location(flat, "case.yaml", kFirstItem + 3, 12, "analyses[0].region.max");
  EXPECT_THAT(flat.message(), HasSubstr("max must exceed min"));
  const InputError extra =
      load_error(with_items(head + "      max: [0.5, 1]\n      cells: [2, 2]\n"));
  expect_location(extra, "case.yaml", kFirstItem + 4, 7, "analyses[0].region.cells");
  EXPECT_THAT(extra.message(), HasSubstr("unknown key 'cells'"));
}

TEST(CaseDischargeAnalyses, MassInRegionBadFitWindows) {
  const std::string head = "  - type: mass_in_region\n    region: {min: [0, 0], max: [1, 1]}\n";
  const InputError empty = load_error(with_items(head + "    fit_from: 0.5\n    fit_until: 0.5\n"));
  expect_location(empty, "case.yaml", kFirstItem + 3, 16, "analyses[0].fit_until");
  EXPECT_THAT(empty.message(), HasSubstr("fit_until must be later than fit_from"));
  const InputError negative = load_error(with_items(head + "    fit_from: -1\n"));
  expect_location(negative, "case.yaml", kFirstItem + 2, 15, "analyses[0].fit_from");
}

TEST(CaseDischargeAnalyses, HeightProfileLoads) {
  const io::Case loaded = load_text(
      with_items("  - {type: height_profile, axis: x, vertical: y, from: 0, to: 1.6, bins: 8}\n"));
  const analysis::HeightLine& line = only_analysis(loaded).height;
  EXPECT_EQ(line.axis, 0);
  EXPECT_EQ(line.vertical, 1);
  EXPECT_EQ(line.from, 0.0);
  EXPECT_DOUBLE_EQ(line.to, 1.6);
  EXPECT_EQ(line.bins, 8);
  EXPECT_EQ(loaded.resolved["analyses"][0]["vertical"], "y");
}

TEST(CaseDischargeAnalyses, HeightProfileIn3D) {
  const io::Case loaded = load_text(with_analyses_3d(
      "  - {type: height_profile, axis: z, vertical: y, from: -0.5, to: 0.5, bins: 3}\n"));
  const analysis::HeightLine& line = only_analysis(loaded).height;
  EXPECT_EQ(line.axis, 2);
  EXPECT_EQ(line.vertical, 1);
  EXPECT_EQ(line.from, -0.5);
  EXPECT_EQ(line.bins, 3);
}

TEST(CaseDischargeAnalyses, HeightProfileBadValues) {
  const std::string head = "  - type: height_profile\n    axis: x\n";
  const std::string span = "    from: 0\n    to: 1\n";
  const InputError same =
      load_error(with_items(head + "    vertical: x\n" + span + "    bins: 4\n"));
  expect_location(same, "case.yaml", kFirstItem + 2, 15, "analyses[0].vertical");
  EXPECT_THAT(same.message(), HasSubstr("vertical must differ from axis"));
  const InputError z = load_error(with_items(head + "    vertical: z\n" + span + "    bins: 4\n"));
  expect_location(z, "case.yaml", kFirstItem + 2, 15, "analyses[0].vertical");
  const std::string axes = head + "    vertical: y\n";
  const InputError reversed =
      load_error(with_items(axes + "    from: 1\n    to: 0.5\n    bins: 4\n"));
  expect_location(reversed, "case.yaml", kFirstItem + 4, 9, "analyses[0].to");
  EXPECT_THAT(reversed.message(), HasSubstr("to must exceed from"));
  const InputError no_bins = load_error(with_items(axes + span));
  EXPECT_EQ(no_bins.location().key_path, "analyses[0].bins") << no_bins.what();
  EXPECT_THAT(no_bins.message(), HasSubstr("missing required key 'bins'"));
  const InputError zero_bins = load_error(with_items(axes + span + "    bins: 0\n"));
  expect_location(zero_bins, "case.yaml", kFirstItem + 5, 11, "analyses[0].bins");
  const InputError many_bins = load_error(with_items(axes + span + "    bins: 1001\n"));
  expect_location(many_bins, "case.yaml", kFirstItem + 5, 11, "analyses[0].bins");
  EXPECT_THAT(many_bins.message(), HasSubstr("at most 1000 bins"));
  const InputError no_axis = load_error(with_items("  - type: height_profile\n"));
  EXPECT_EQ(no_axis.location().key_path, "analyses[0].axis") << no_axis.what();
}

}  // namespace
}  // namespace partimix::case_test
