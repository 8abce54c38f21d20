// The analyses body_loads, power_number, mixing and droplet and the key fluid.tracer
// (docs/case-reference.md, "fluid" and "analyses"): they load with their values and defaults
// (recorded in the resolved case), and bad ones are InputErrors naming file, line, column and
// key path.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include <string>
#include <vector>

#include "case_files.hpp"
#include "support/multi_material_case.hpp"
#include "support/sph_case.hpp"

namespace partimix::case_test {
namespace {

using ::testing::HasSubstr;

// Four walls after kMinimal2D: 0 a fixed box; 1 a plate turning at 60 rpm about (0.25, 0.5);
// 2 a plate in planetary motion, its own axis through (0.3, 0.5) revolving at 30 rpm about
// (0.25, 0.5) (e'' = 0.05 m, d_G = 0.1 m) with spin 60 rpm; 3 the same revolving at -60 rpm.
const std::string kWalls = R"(walls:
  - shape: box
    min: [0, 0]
    max: [1.6, 1.0]
  - shape: plate
    centre: [0.25, 0.5]
    length: 0.2
    width: 0.04
    solid: true
    motion: {type: rotation, axis_point: [0.25, 0.5], rpm: 60}
  - shape: plate
    centre: [0.3, 0.5]
    length: 0.1
    width: 0.04
    solid: true
    motion:
      type: planetary
      axis_point: [0.3, 0.5]
      centre: [0.25, 0.5]
      rpm: 60
      revolution_rpm: 30
  - shape: plate
    centre: [0.3, 0.5]
    length: 0.1
    width: 0.04
    solid: true
    motion:
      type: planetary
      axis_point: [0.3, 0.5]
      centre: [0.25, 0.5]
      rpm: 60
      revolution_rpm: -60
analyses:
)";

const std::string kTracer = "  tracer: {point: [0, 0.5]}\n";

// kMinimal2D, then `fluid_lines` (in the fluid map), the walls and the analyses list `items`.
std::string with_analyses(const std::string& items, const std::string& fluid_lines = "") {
  return kMinimal2D + fluid_lines + kWalls + items;
}

// The 1-based line of the first analysis item when the fluid map gets `fluid_lines`.
int first_item_line(const std::string& fluid_lines = "") {
  return static_cast<int>(lines_of(with_analyses("", fluid_lines)).size()) + 1;
}

const io::AnalysisSpec& only_analysis(const io::Case& loaded) {
  EXPECT_EQ(loaded.analyses.size(), 1u);
  return loaded.analyses.at(0);
}

TEST(CaseAnalyses, BodyLoadsDefaults) {
  // A rotating body: the vessel axis point defaults to the origin, one revolution.
  const io::Case loaded = load_text(with_analyses("  - {type: body_loads, body: 1}\n"));
  const io::AnalysisSpec& spec = only_analysis(loaded);
  EXPECT_EQ(spec.type, "body_loads");
  EXPECT_EQ(spec.body, 1);
  EXPECT_EQ(spec.vessel_axis_point, Vec3::Zero());
  EXPECT_DOUBLE_EQ(spec.average_revolutions, 1.0);
  const auto& resolved = loaded.resolved["analyses"][0];
  EXPECT_EQ(resolved["average_revolutions"], 1.0);
  EXPECT_EQ(resolved["vessel_axis_point"], nlohmann::json::parse("[0.0, 0.0]"));
}

TEST(CaseAnalyses, PlanetaryVesselAxisPointDefaultsToTheMotionCentre) {
  const io::Case loaded = load_text(with_analyses("  - {type: body_loads, body: 2}\n"));
  EXPECT_EQ(only_analysis(loaded).vessel_axis_point, Vec3(0.25, 0.5, 0.0));
}

TEST(CaseAnalyses, BodyLoadsExplicitValues) {
  const io::Case loaded =
      load_text(with_analyses("  - {type: body_loads, body: 2, vessel_axis_point: [0.1, 0.2], "
                              "average_revolutions: 2.5}\n"));
  const io::AnalysisSpec& spec = only_analysis(loaded);
  EXPECT_EQ(spec.body, 2);
  EXPECT_EQ(spec.vessel_axis_point, Vec3(0.1, 0.2, 0.0));
  EXPECT_DOUBLE_EQ(spec.average_revolutions, 2.5);
}

TEST(CaseAnalyses, PowerNumberDefaults) {
  const io::Case loaded =
      load_text(with_analyses("  - {type: power_number, body: 1, diameter: 0.2}\n"));
  const io::AnalysisSpec& spec = only_analysis(loaded);
  EXPECT_EQ(spec.type, "power_number");
  EXPECT_EQ(spec.body, 1);
  EXPECT_DOUBLE_EQ(spec.diameter, 0.2);
  EXPECT_DOUBLE_EQ(spec.metzner_otto, 7.54);
  EXPECT_DOUBLE_EQ(spec.average_revolutions, 1.0);
  EXPECT_EQ(loaded.resolved["analyses"][0]["metzner_otto"], 7.54);
}

TEST(CaseAnalyses, PowerNumberOfAPlanetaryBodyWithItsOwnConstant) {
  // u_ch = 0.5 0.1 + 1 0.08 > 0.
  const io::Case loaded =
      load_text(with_analyses("  - {type: power_number, body: 2, diameter: 0.08, metzner_otto: 11, "
                              "average_revolutions: 3}\n"));
  const io::AnalysisSpec& spec = only_analysis(loaded);
  EXPECT_DOUBLE_EQ(spec.metzner_otto, 11.0);
  EXPECT_DOUBLE_EQ(spec.average_revolutions, 3.0);
  EXPECT_EQ(spec.vessel_axis_point, Vec3(0.25, 0.5, 0.0));
}

TEST(CaseAnalyses, PowerNumberTakesPowerLawAndHerschelBulkleyFluids) {
  for (const char* rheology :
       {"{model: power_law, consistency: 13.9, flow_index: 0.47, viscosity_max: 1.0e4}",
        "{model: herschel_bulkley, yield_stress: 5, consistency: 13.9, flow_index: 0.47, "
        "viscosity_max: 1.0e4}"}) {
    const std::string text =
        replace_line(with_analyses("  - {type: power_number, body: 1, diameter: 0.2}\n"), 13,
                     std::string("  rheology: ") + rheology);
    EXPECT_EQ(load_text(text).analyses.size(), 1u) << rheology;
  }
}

TEST(CaseAnalyses, TracerLoadsWithTheSeedsNormalByDefault) {
  const io::Case loaded = load_text(with_analyses("", kTracer));
  ASSERT_TRUE(test_support::fluid_of(loaded).tracer.has_value());
  EXPECT_EQ(test_support::fluid_of(loaded).tracer->point, Vec3(0.0, 0.5, 0.0));
  EXPECT_EQ(test_support::fluid_of(loaded).tracer->normal, Vec3(0.0, -1.0, 0.0));
  EXPECT_FALSE(test_support::fluid_of(load_text(kMinimal2D)).tracer.has_value());
}

TEST(CaseAnalyses, MixingDiscDefaults) {
  // 2D: a disc (z over [-1, 1]) of [rings, sectors], one layer; min_count 1.
  const io::Case loaded = load_text(with_analyses(
      "  - {type: mixing, axis_point: [0.25, 0.5], radius: 0.2, cells: [2, 4]}\n", kTracer));
  const io::AnalysisSpec& spec = only_analysis(loaded);
  EXPECT_EQ(spec.type, "mixing");
  const analysis::MixingRegion& region = spec.mixing;
  EXPECT_TRUE(region.cylinder);
  EXPECT_EQ(region.cylinder_region.axis_point, Vec3(0.25, 0.5, 0.0));
  EXPECT_EQ(region.cylinder_region.axis, Vec3::UnitZ());
  EXPECT_DOUBLE_EQ(region.cylinder_region.radius, 0.2);
  EXPECT_DOUBLE_EQ(region.cylinder_region.z0, -1.0);
  EXPECT_DOUBLE_EQ(region.cylinder_region.z1, 1.0);
  EXPECT_EQ(region.cells, (std::array<int, 3>{2, 4, 1}));
  EXPECT_EQ(region.min_count, 1);
  EXPECT_EQ(loaded.resolved["analyses"][0]["region"], "cylinder");
  EXPECT_EQ(loaded.resolved["analyses"][0]["min_count"], 1);
}

TEST(CaseAnalyses, MixingBox) {
  const io::Case loaded = load_text(
      with_analyses("  - {type: mixing, region: box, min: [0, 0], max: [0.5, 1], cells: [2, 3], "
                    "min_count: 5}\n",
                    kTracer));
  const analysis::MixingRegion& region = only_analysis(loaded).mixing;
  EXPECT_FALSE(region.cylinder);
  EXPECT_EQ(region.lo, Vec3(0.0, 0.0, 0.0));
  EXPECT_EQ(region.hi, Vec3(0.5, 1.0, 0.0));
  EXPECT_EQ(region.cells, (std::array<int, 3>{2, 3, 1}));
  EXPECT_EQ(region.min_count, 5);
}

TEST(CaseAnalyses, AnalysesKeepTheirOrder) {
  const io::Case loaded = load_text(with_analyses(R"(  - {type: mixing, radius: 0.2, cells: [1, 2]}
  - {type: power_number, body: 1, diameter: 0.2}
  - {type: body_loads, body: 1}
  - {type: front_position}
)",
                                                  kTracer));
  ASSERT_EQ(loaded.analyses.size(), 4u);
  EXPECT_EQ(loaded.analyses[0].type, "mixing");
  EXPECT_EQ(loaded.analyses[1].type, "power_number");
  EXPECT_EQ(loaded.analyses[2].type, "body_loads");
  EXPECT_EQ(loaded.analyses[3].type, "front_position");
}

TEST(CaseAnalyses, MixingCylinderIn3D) {
  const io::Case loaded = load_text(with_analyses_3d(
      "  - {type: mixing, axis_point: [0.5, 0.5, 0], axis: [0, 0, 2], radius: 0.3, bottom: 0.1, "
      "top: 0.45, cells: [2, 4, 3]}\n"));
  EXPECT_EQ(test_support::fluid_of(loaded).tracer->normal, Vec3(0.0, -1.0, 0.0));
  const analysis::CylinderRegion& cylinder = only_analysis(loaded).mixing.cylinder_region;
  EXPECT_EQ(cylinder.axis_point, Vec3(0.5, 0.5, 0.0));
  EXPECT_EQ(cylinder.axis.normalized(), Vec3::UnitZ());
  EXPECT_DOUBLE_EQ(cylinder.z0, 0.1);
  EXPECT_DOUBLE_EQ(cylinder.z1, 0.45);
  EXPECT_EQ(only_analysis(loaded).mixing.cells, (std::array<int, 3>{2, 4, 3}));
}

TEST(CaseAnalyses, BodyOutOfRange) {
  const int line = first_item_line();
  const InputError error = load_error(with_analyses("  - type: body_loads\n    body: 4\n"));
  expect_location(error, "case.yaml", line + 1, 11, "analyses[0].body");
  EXPECT_THAT(error.message(), HasSubstr("there is no wall 4 (the case has 4 walls"));
}

TEST(CaseAnalyses, PowerNumberOnAFixedWall) {
  const int line = first_item_line();
  const InputError error =
      load_error(with_analyses("  - type: power_number\n    body: 0\n    diameter: 0.1\n"));
  expect_location(error, "case.yaml", line + 1, 11, "analyses[0].body");
  EXPECT_THAT(error.message(),
              HasSubstr("wall 0: power numbers need a body in rotation or planetary motion"));
}

TEST(CaseAnalyses, PowerNumberRefusesCrossAndCarreauFluids) {
  const int line = first_item_line();
  for (const std::string& model : {std::string("cross"), std::string("carreau")}) {
    const std::string text = replace_line(
        with_analyses("  - type: power_number\n    body: 1\n    diameter: 0.1\n"), 13,
        "  rheology: {model: " + model +
            ", zero_shear_viscosity: 1, infinite_shear_viscosity: 0.01, time_constant: 0.1, "
            "flow_index: 0.5}");
    const InputError error = load_error(text);
    expect_location(error, "case.yaml", line, 11, "analyses[0].type");
    EXPECT_THAT(error.message(),
                HasSubstr("need a newtonian, power_law or herschel_bulkley fluid"));
    EXPECT_THAT(error.message(), HasSubstr("method sph has none")) << model;
  }
}

TEST(CaseAnalyses, PlanetaryWithoutAPositiveUch) {
  // Wall 3: N_G = -1 r/s, d_G = 0.1, N_R = 1 r/s, d_R = 0.05: u_ch = -0.1 + 0.05 < 0.
  const int line = first_item_line();
  const InputError error =
      load_error(with_analyses("  - type: power_number\n    body: 3\n    diameter: 0.05\n"));
  expect_location(error, "case.yaml", line + 1, 11, "analyses[0].body");
  EXPECT_THAT(error.message(), HasSubstr("wall 3: eq. 31 needs u_ch"));
}

TEST(CaseAnalyses, DiameterIsRequiredAndPositive) {
  const int line = first_item_line();
  const InputError missing = load_error(with_analyses("  - type: power_number\n    body: 1\n"));
  EXPECT_EQ(missing.location().key_path, "analyses[0].diameter") << missing.what();
  const InputError zero =
      load_error(with_analyses("  - type: power_number\n    body: 1\n    diameter: 0\n"));
  expect_location(zero, "case.yaml", line + 2, 15, "analyses[0].diameter");
  EXPECT_THAT(zero.message(), HasSubstr("must be > 0"));
}

TEST(CaseAnalyses, KeysOfOtherAnalysesAreUnknown) {
  const int line = first_item_line();
  const InputError error =
      load_error(with_analyses("  - type: body_loads\n    body: 1\n    diameter: 0.1\n"));
  expect_location(error, "case.yaml", line + 2, 5, "analyses[0].diameter");
  EXPECT_THAT(error.message(), HasSubstr("unknown key 'diameter'"));
}

TEST(CaseAnalyses, AverageRevolutionsMustBePositive) {
  const int line = first_item_line();
  const InputError error =
      load_error(with_analyses("  - type: body_loads\n    body: 1\n    average_revolutions: 0\n"));
  expect_location(error, "case.yaml", line + 2, 26, "analyses[0].average_revolutions");
}

TEST(CaseAnalyses, MixingNeedsATracer) {
  const int line = first_item_line();
  const InputError error =
      load_error(with_analyses("  - type: mixing\n    radius: 0.2\n    cells: [2, 4]\n"));
  expect_location(error, "case.yaml", line, 11, "analyses[0].type");
  EXPECT_THAT(error.message(), HasSubstr("fluid.tracer for sph"));
}

TEST(CaseAnalyses, CellCountsMustBeWholeNumbersOfAtLeastOne) {
  const int line = first_item_line(kTracer);
  for (const char* cells : {"[0, 4]", "[2, 1.5]", "[2, -1]"}) {
    const InputError error = load_error(with_analyses(
        std::string("  - type: mixing\n    radius: 0.2\n    cells: ") + cells + "\n", kTracer));
    expect_location(error, "case.yaml", line + 2, 12, "analyses[0].cells");
    EXPECT_THAT(error.message(), HasSubstr("whole numbers of at least 1")) << cells;
  }
}

TEST(CaseAnalyses, AtMostTenMillionCellsInAll) {
  // 4000 x 2500 = 10^7 is allowed; one more ring is not, and neither is a count past int's range.
  EXPECT_NO_THROW(load_text(
      with_analyses("  - type: mixing\n    radius: 0.2\n    cells: [4000, 2500]\n", kTracer)));
  const int line = first_item_line(kTracer);
  for (const char* cells : {"[4001, 2500]", "[1, 1.0e12]"}) {
    const InputError error = load_error(with_analyses(
        std::string("  - type: mixing\n    radius: 0.2\n    cells: ") + cells + "\n", kTracer));
    expect_location(error, "case.yaml", line + 2, 12, "analyses[0].cells");
    EXPECT_THAT(error.message(), HasSubstr("at most 1e+07 cells in all")) << cells;
  }
}

TEST(CaseAnalyses, MinCountMustBeAtLeastOne) {
  const int line = first_item_line(kTracer);
  const InputError error = load_error(with_analyses(
      "  - type: mixing\n    radius: 0.2\n    cells: [2, 4]\n    min_count: 0\n", kTracer));
  expect_location(error, "case.yaml", line + 3, 16, "analyses[0].min_count");
}

TEST(CaseAnalyses, BoxMaxMustExceedMin) {
  const int line = first_item_line(kTracer);
  const InputError error = load_error(with_analyses(
      "  - type: mixing\n    region: box\n    min: [0, 0]\n    max: [0.5, 0]\n    cells: [2, 2]\n",
      kTracer));
  expect_location(error, "case.yaml", line + 3, 10, "analyses[0].max");
}

TEST(CaseAnalyses, DiscTakesNoAxialSpanIn2D) {
  const int line = first_item_line(kTracer);
  const InputError error = load_error(with_analyses(
      "  - type: mixing\n    radius: 0.2\n    cells: [2, 4]\n    bottom: 0\n", kTracer));
  expect_location(error, "case.yaml", line + 3, 5, "analyses[0].bottom");
}

TEST(CaseAnalyses, TopMustLieAboveBottom) {
  // top is on the fifth line of the items, its value at column 10.
  const InputError error = load_error(with_analyses_3d(
      "  - type: mixing\n    radius: 0.3\n    cells: [2, 4, 3]\n    bottom: 0.4\n    top: 0.4\n"));
  expect_location(error, "case.yaml", kFirstAnalysis3D + 4, 10, "analyses[0].top");
  EXPECT_THAT(error.message(), HasSubstr("top must lie above bottom"));
}

TEST(CaseAnalyses, TracerNormalMustNotBeZero) {
  // kMinimal2D has 17 lines: the tracer is line 18, its normal's value at column 20.
  const InputError error = load_error(with_analyses("", "  tracer: {normal: [0, 0]}\n"));
  expect_location(error, "case.yaml", 18, 20, "fluid.tracer.normal");
  EXPECT_THAT(error.message(), HasSubstr("must not be the zero vector"));
}

TEST(CaseAnalyses, AnOwnScheduleNeedsANameAndStaysWithinTheLimit) {
  const InputError unnamed =
      load_error(with_analyses_3d("  - {type: front_position, axis: x, sample_interval: 0.01}\n"));
  EXPECT_EQ(unnamed.location().key_path, "analyses[0].sample_interval");
  EXPECT_THAT(unnamed.message(), HasSubstr("needs a `name`"));
  const InputError stray =
      load_error(with_analyses_3d("  - {type: front_position, axis: x, sample_from: 0.5}\n"));
  EXPECT_EQ(stray.location().key_path, "analyses[0].sample_from");
  const InputError too_many = load_error(
      with_analyses_3d("  - {type: front_position, axis: x, name: f, sample_interval: 1.0e-9}\n"));
  EXPECT_THAT(too_many.message(), HasSubstr("more than limits.series_rows"));
  const io::Case loaded = load_text(with_analyses_3d(
      "  - {type: front_position, axis: x, name: f, sample_interval: 0.01, sample_from: 0.2}\n"));
  EXPECT_EQ(loaded.analyses[0].sample_interval, 0.01);
  EXPECT_EQ(loaded.analyses[0].sample_from, 0.2);
  EXPECT_TRUE(std::isinf(loaded.analyses[0].sample_until));
}

// sample_until defaults to the end of the run, written `auto` in the resolved case: a run
// resumed with a later time.end resolves the analysis the same way, so the checkpoint fits (the
// default was time.end itself, which made the resumed case differ at sample_until).
TEST(CaseAnalyses, TheDefaultSampleUntilFollowsTheEndOfTheRun) {
  const std::string text =
      with_analyses_3d("  - {type: front_position, axis: x, name: f, sample_interval: 0.01}\n");
  const io::Case shorter = load_text(text);
  const io::Case longer = load_text(text, {"time.end=" + std::to_string(2.0 * shorter.time.end)});
  EXPECT_EQ(shorter.resolved.at("analyses"), longer.resolved.at("analyses"));
  EXPECT_EQ(shorter.resolved.at("analyses")[0].at("sample_until"), "auto");
}

TEST(CaseAnalyses, TwoAnalysesOfOneNameAreRefused) {
  const InputError error =
      load_error(with_analyses_3d("  - {type: front_position, axis: x, name: f}\n  - {type: "
                                  "front_position, axis: y, name: f}\n"));
  EXPECT_EQ(error.location().key_path, "analyses[1].name");
  EXPECT_THAT(error.message(), HasSubstr("analyses[0] has this name already"));
}

// A 2D droplet of the multi-material scheme (spacing 0.01 m): materials fuel 0, shell 1,
// vapour 2 and air 3, with the analyses list `items`.
std::string droplet_case(const std::string& items) {
  std::string materials;
  for (const char* name : {"fuel", "shell", "vapour", "air"}) {
    materials += std::string("    - name: ") + name +
                 "\n      eos: {model: tait, reference_density: 800, sound_speed: 50}\n"
                 "      specific_heat: 2000\n";
  }
  return test_support::multi_material_case(materials,
                                           test_support::region_with("      material: fuel\n")) +
         "analyses:\n" + items;
}
TEST(CaseAnalyses, DropletNamesItsMaterialsByIndexAndLinksOneAndAHalfSpacings) {
  const io::Case loaded =
      load_text(droplet_case("  - {type: droplet, shell: shell, gas: [air, vapour]}\n"));
  const analysis::DropletOptions& droplet = only_analysis(loaded).droplet;
  EXPECT_EQ(droplet.shell, 1);
  EXPECT_EQ(droplet.gas, (std::vector<int>{3, 2}));
  EXPECT_DOUBLE_EQ(droplet.link, 0.015);
  EXPECT_DOUBLE_EQ(droplet.after_rupture, 0.1);
  EXPECT_EQ(droplet.dimensions, 2);
  EXPECT_DOUBLE_EQ(loaded.resolved.at("analyses")[0].at("link"), 0.015);
  const io::Case one_gas =
      load_text(droplet_case("  - {type: droplet, shell: shell, gas: vapour, link: 0.02, "
                             "after_rupture: 6.7e-5}\n"));
  EXPECT_EQ(only_analysis(one_gas).droplet.gas, (std::vector<int>{2}));
  EXPECT_DOUBLE_EQ(only_analysis(one_gas).droplet.link, 0.02);
  EXPECT_DOUBLE_EQ(only_analysis(one_gas).droplet.after_rupture, 6.7e-5);
}

TEST(CaseAnalyses, DropletShellMustBeAMaterial) {
  const int line = static_cast<int>(lines_of(droplet_case("")).size()) + 1;
  const InputError error =
      load_error(droplet_case("  - type: droplet\n    shell: gel\n    gas: vapour\n"));
  expect_location(error, "case.yaml", line + 1, 12, "analyses[0].shell");
  EXPECT_THAT(error.message(), HasSubstr("unknown value 'gel'; expected one of: fuel, shell"));
}

TEST(CaseAnalyses, DropletGasMustNotBeTheShell) {
  const InputError error =
      load_error(droplet_case("  - type: droplet\n    shell: shell\n    gas: [vapour, shell]\n"));
  EXPECT_EQ(error.location().key_path, "analyses[0].gas") << error.what();
  EXPECT_THAT(error.message(), HasSubstr("'shell' is the shell's material"));
}

TEST(CaseAnalyses, DropletNeedsTheMultiMaterialScheme) {
  const int line = first_item_line();
  const InputError error =
      load_error(with_analyses("  - type: droplet\n    shell: shell\n    gas: vapour\n"));
  expect_location(error, "case.yaml", line, 11, "analyses[0].type");
  EXPECT_THAT(error.message(), HasSubstr("needs sph.scheme: multi_material"));
}

}  // namespace
}  // namespace partimix::case_test
