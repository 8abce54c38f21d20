// Each kind of bad input is an InputError naming file, line, column and key path.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "case_files.hpp"

namespace partimix::case_test {
namespace {

using ::testing::HasSubstr;

TEST(CaseErrors, MalformedYamlNamesTheParserPosition) {
  const InputError error = load_error(replace_line(kMinimal2D, 5, "  max: [1.6, 1.0"));
  EXPECT_EQ(error.location().line, 6) << error.what();
  EXPECT_GT(error.location().column, 0) << error.what();
  EXPECT_EQ(error.location().key_path, "");
  EXPECT_THAT(error.message(), HasSubstr("malformed YAML"));
}

TEST(CaseErrors, MissingFileIsAnInputError) {
  const std::string path = "/nonexistent/partimix/case.yaml";
  try {
    io::load_case(path);
    ADD_FAILURE() << "expected an InputError";
  } catch (const InputError& error) {
    expect_location(error, path, 0, 0, "");
    EXPECT_THAT(error.message(), HasSubstr("cannot read"));
  }
}

TEST(CaseErrors, EmptyFileIsNotACase) {
  const InputError error = load_error("");
  expect_location(error, "case.yaml", 0, 0, "");
  EXPECT_THAT(error.message(), HasSubstr("expected a map of case keys, got nothing"));
}

TEST(CaseErrors, UnknownTopLevelKeyListsTheKnownKeys) {
  const InputError error = load_error(insert_line(kMinimal2D, 3, "kernal: x"));
  expect_location(error, "case.yaml", 3, 1, "kernal");
  EXPECT_THAT(error.message(), HasSubstr("unknown key 'kernal'; expected one of: name, "
                                         "description, solver, dimensions, gravity, domain"));
}

TEST(CaseErrors, UnknownNestedKeyListsTheSectionKeys) {
  const InputError error = load_error(insert_line(kMinimal2D, 11, "  kernal: wendland_c2"));
  expect_location(error, "case.yaml", 11, 3, "sph.kernal");
  EXPECT_THAT(error.message(),
              HasSubstr("unknown key 'kernal'; expected one of: spacing, smoothing_ratio, kernel"));
}

// docs/sph.md, "Variable smoothing length": the incompressible scheme keeps rho = rho0.
TEST(CaseErrors, VariableSmoothingLengthNeedsACompressibleScheme) {
  const std::string text = insert_line(insert_line(kMinimal2D, 11, "  scheme: incompressible"), 12,
                                       "  smoothing_length: variable");
  const InputError error = load_error(text);
  expect_location(error, "case.yaml", 12, 21, "sph.smoothing_length");
  EXPECT_THAT(error.message(), HasSubstr("h cannot vary"));
}

TEST(CaseErrors, UnknownKeyInAListItemNamesTheItem) {
  const InputError error = load_error(kMinimal2D + "      radius: 0.1\n");
  expect_location(error, "case.yaml", 18, 7, "fluid.regions[0].radius");
  EXPECT_THAT(error.message(), HasSubstr("expected one of: shape, min, max"));
}

TEST(CaseErrors, StringForANumber) {
  const InputError error = load_error(replace_line(kMinimal2D, 10, "  spacing: abc"));
  expect_location(error, "case.yaml", 10, 12, "sph.spacing");
  EXPECT_EQ(error.message(), "expected a number, got 'abc'");
}

TEST(CaseErrors, EmptyValueForANumber) {
  const InputError error = load_error(replace_line(kMinimal2D, 10, "  spacing:"));
  EXPECT_EQ(error.location().key_path, "sph.spacing");
  EXPECT_EQ(error.message(), "expected a number, got nothing");
}

TEST(CaseErrors, FractionForAnInteger) {
  const InputError error = load_error(insert_line(kMinimal2D, 11, "  sort_interval: 1.5"));
  expect_location(error, "case.yaml", 11, 18, "sph.sort_interval");
  EXPECT_EQ(error.message(), "expected an integer, got '1.5'");
}

TEST(CaseErrors, MapWhereAListIsExpected) {
  std::string text = replace_line(kMinimal2D, 15, "    shape: box");
  text = replace_line(text, 16, "    min: [0, 0]");
  text = replace_line(text, 17, "    max: [0.5, 1.0]");
  const InputError error = load_error(text);
  expect_location(error, "case.yaml", 15, 5, "fluid.regions");
  EXPECT_EQ(error.message(), "expected a list, got a map");
}

TEST(CaseErrors, ScalarWhereAMapIsExpected) {
  const InputError error = load_error(kMinimal2D + "output: yes\n");
  expect_location(error, "case.yaml", 18, 9, "output");
  EXPECT_EQ(error.message(), "expected a map, got 'yes'");
}

TEST(CaseErrors, MissingRequiredKeyPointsAtItsMap) {
  const InputError error = load_error(remove_line(kMinimal2D, 7));
  expect_location(error, "case.yaml", 7, 3, "time.end");
  EXPECT_EQ(error.message(), "missing required key 'end'");
}

TEST(CaseErrors, MissingTopLevelSection) {
  const InputError error = load_error(remove_line(remove_line(kMinimal2D, 10), 9));
  expect_location(error, "case.yaml", 1, 1, "sph");
  EXPECT_EQ(error.message(), "missing required key 'sph'");
}

TEST(CaseErrors, EmptyRegionListIsAnError) {
  std::string text = replace_line(kMinimal2D, 14, "  regions: []");
  text = remove_line(remove_line(remove_line(text, 17), 16), 15);
  const InputError error = load_error(text);
  expect_location(error, "case.yaml", 14, 12, "fluid.regions");
  EXPECT_EQ(error.message(), "must have at least one item");
}

TEST(CaseErrors, NonPositiveSpacing) {
  const InputError error = load_error(replace_line(kMinimal2D, 10, "  spacing: -1"));
  expect_location(error, "case.yaml", 10, 12, "sph.spacing");
  EXPECT_EQ(error.message(), "must be > 0, got -1");
}

TEST(CaseErrors, NegativeViscosity) {
  const InputError error = load_error(replace_line(kMinimal2D, 13, "  viscosity: -1e-3"));
  expect_location(error, "case.yaml", 13, 14, "fluid.viscosity");
  EXPECT_EQ(error.message(), "must be >= 0, got -1e-3");
}

TEST(CaseErrors, ZeroSortInterval) {
  const InputError error = load_error(insert_line(kMinimal2D, 11, "  sort_interval: 0"));
  EXPECT_EQ(error.location().key_path, "sph.sort_interval");
  EXPECT_EQ(error.message(), "must be >= 1, got 0");
}

TEST(CaseErrors, InfiniteNumber) {
  const InputError error = load_error(replace_line(kMinimal2D, 7, "  end: .inf"));
  EXPECT_EQ(error.location().key_path, "time.end");
  EXPECT_EQ(error.message(), "expected a finite number, got '.inf'");
}

TEST(CaseErrors, DimensionsOtherThanTwoOrThree) {
  const InputError error = load_error(replace_line(kMinimal2D, 2, "dimensions: 4"));
  expect_location(error, "case.yaml", 2, 13, "dimensions");
  EXPECT_EQ(error.message(), "must be 2 or 3, got 4");
}

TEST(CaseErrors, BadEnumValueListsTheAllowedValues) {
  const InputError error = load_error(insert_line(kMinimal2D, 11, "  kernel: foo"));
  expect_location(error, "case.yaml", 11, 11, "sph.kernel");
  EXPECT_EQ(error.message(),
            "unknown value 'foo'; expected one of: cubic_spline, hyperbolic, wendland_c2");
}

TEST(CaseErrors, PeriodicZIn2D) {
  const InputError error = load_error(insert_line(kMinimal2D, 6, "  periodic: [x, z]"));
  expect_location(error, "case.yaml", 6, 17, "domain.periodic[1]");
  EXPECT_EQ(error.message(), "unknown value 'z'; expected one of: x, y");
}

TEST(CaseErrors, VectorWithTheWrongNumberOfComponents) {
  const InputError error = load_error(replace_line(kMinimal2D, 5, "  max: [1.6, 1.0, 2.0]"));
  expect_location(error, "case.yaml", 5, 8, "domain.max");
  EXPECT_EQ(error.message(), "expected 2 components (dimensions is 2), got 3");
}

TEST(CaseErrors, BadVectorComponentNamesItsIndex) {
  const InputError error = load_error(replace_line(kMinimal2D, 17, "      max: [0.5, abc]"));
  expect_location(error, "case.yaml", 17, 18, "fluid.regions[0].max[1]");
  EXPECT_EQ(error.message(), "expected a number, got 'abc'");
}

TEST(CaseErrors, MeshIn2D) {
  const InputError error = load_error(replace_line(kMinimal2D, 15, "    - shape: mesh"));
  expect_location(error, "case.yaml", 15, 14, "fluid.regions[0].shape");
  EXPECT_THAT(error.message(), HasSubstr("mesh needs dimensions: 3"));
}

TEST(CaseErrors, CylinderHeightIn2D) {
  const std::string text = kMinimal2D + R"(walls:
  - {shape: cylinder, center: [0.5, 0.5], radius: 0.4, height: 1}
)";
  const InputError error = load_error(text);
  EXPECT_EQ(error.location().key_path, "walls[0].height");
  EXPECT_THAT(error.message(), HasSubstr("in 2D it is a circle"));
}

TEST(CaseErrors, DomainMaxNotAboveMin) {
  const InputError error = load_error(replace_line(kMinimal2D, 5, "  max: [1.6, 0]"));
  expect_location(error, "case.yaml", 5, 8, "domain.max");
  EXPECT_EQ(error.message(), "must be > min on every axis; y: max 0 <= min 0");
}

TEST(CaseErrors, WhatReadsFileLineColumnKeyPathMessage) {
  const InputError error = load_error(replace_line(kMinimal2D, 10, "  spacing: -1"));
  EXPECT_THAT(std::string(error.what()),
              ::testing::EndsWith("case.yaml:10:12: sph.spacing: must be > 0, got -1"));
}

}  // namespace
}  // namespace partimix::case_test
