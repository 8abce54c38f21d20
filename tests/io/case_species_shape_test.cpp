// dem.species[].shape (docs/case-reference.md, "dem"): superquadric grains by their half-axes,
// or by the seed's aspect ratio and equal-volume radius, and their Hertz radius; every bad value
// is located.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "case_files.hpp"
#include "dem/dem_section.hpp"

namespace partimix::case_test {
namespace {

using ::testing::HasSubstr;

const std::string kHeader = R"(solver: dem
dimensions: 3
domain: {min: [-1, -1, -1], max: [1, 1, 1]}
time: {end: 1.0, output_interval: 0.1}
dem:
)";

// A case whose one species has `shape`, filled at random.
std::string with_shape(const std::string& shape, const std::string& fill_extra = "") {
  return kHeader + R"(  species:
    - {name: a, density: 2500, shape: )" +
         shape + R"(}
  fill:
    region: {shape: box, min: [-0.5, -0.5, -0.5], max: [0.5, 0.5, 0.5]}
    count: 10
)" + fill_extra;
}

const dem::Species& species_of(const io::Case& the_case) {
  return the_case.section<dem::DemSection>("dem").config.species.front();
}

TEST(CaseSpeciesShape, HalfAxesOrAspectRatioWithTheEqualVolumeRadius) {
  const io::Case axes =
      load_text(with_shape("{half_axes: [0.001, 0.002, 0.003], blockiness: [4, 6]}"));
  const dem::Superquadric& given = *species_of(axes).shape;
  EXPECT_EQ(given.half_axes(), Vec3(0.001, 0.002, 0.003));
  EXPECT_EQ(given.n1(), 4.0);
  EXPECT_EQ(given.n2(), 6.0);
  const io::Case seed = load_text(with_shape("{aspect_ratio: 2, equivalent_radius: 0.002}"));
  const dem::Superquadric& prolate = *species_of(seed).shape;
  const double a = 0.002 / std::cbrt(2.0);  // a^2 (2 a) = r^3 for an ellipsoid
  EXPECT_NEAR(prolate.half_axes().x(), a, 1e-15);
  EXPECT_NEAR(prolate.half_axes().z(), 2.0 * a, 1e-15);
  EXPECT_NEAR(prolate.equivalent_radius(), 0.002, 1e-15);
  EXPECT_FALSE(species_of(load_text(kHeader + R"(  species: [{name: a, density: 2500}]
  fill: {region: {shape: box, min: [0, 0, 0], max: [1, 1, 1]}, count: 1, radius: 0.01}
)"))
                   .shape);
}

TEST(CaseSpeciesShape, BadShapesAreLocated) {
  struct Bad {
    std::string shape;
    std::string fill_extra;
    std::string key;
    std::string message;
  };
  for (const Bad& bad :
       std::vector<Bad>{{"{half_axes: [0.001, 0.002, 0.003], blockiness: [1.5, 2]}", "",
                         "blockiness", "n1 and n2 must lie in [2, 20]"},
                        {"{half_axes: [0.001, 0, 0.003]}", "", "half_axes", "must be positive"},
                        {"{half_axes: [1, 1, 1], aspect_ratio: 2, equivalent_radius: 1}", "",
                         "half_axes", "give either half_axes"},
                        {"{blockiness: [2, 2]}", "", "half_axes", "give either half_axes"},
                        {"{aspect_ratio: 1000, equivalent_radius: 0.001}", "", "aspect_ratio",
                         "must lie in [0.01, 100]"},
                        {"{aspect_ratio: 2}", "", "equivalent_radius", ""},
                        {"{half_axes: [0.001, 0.001, 0.002]}", "    radius: 0.001\n", "radius",
                         "take their size from species[].shape"}}) {
    const InputError error = load_error(with_shape(bad.shape, bad.fill_extra));
    EXPECT_THAT(error.location().key_path, HasSubstr(bad.key)) << bad.shape;
    EXPECT_THAT(error.message(), HasSubstr(bad.message)) << bad.shape;
    EXPECT_GT(error.location().line, 0) << bad.shape;
  }
}

TEST(CaseSpeciesShape, HertzRadiusOptionAndItsLimit) {
  const std::string shape = "{half_axes: [0.001, 0.001, 0.002]}";
  const auto config_of = [](const io::Case& the_case) {
    return the_case.section<dem::DemSection>("dem").config;
  };
  EXPECT_EQ(config_of(load_text(with_shape(shape))).hertz_radius, dem::HertzRadius::equivalent);
  const dem::Config chosen = config_of(
      load_text(with_shape(shape, "  hertz_radius: gaussian_curvature\n  curvature_limit: 4\n")));
  EXPECT_EQ(chosen.hertz_radius, dem::HertzRadius::gaussian_curvature);
  EXPECT_EQ(chosen.curvature_limit, 4.0);
  const InputError unknown = load_error(with_shape(shape, "  hertz_radius: local\n"));
  EXPECT_EQ(unknown.location().key_path, "dem.hertz_radius");
  EXPECT_GT(unknown.location().line, 0);
  const InputError below = load_error(with_shape(shape, "  curvature_limit: 0.5\n"));
  EXPECT_EQ(below.location().key_path, "dem.curvature_limit");
}

TEST(CaseSpeciesShape, ListedSuperquadricsTakeTheirSizeFromTheShape) {
  const std::string listed =
      kHeader + R"(  species: [{name: a, density: 2500, shape: {half_axes: [0.001, 0.001, 0.003]}}]
  grains:
)";
  const io::Case loaded = load_text(listed + "    - {position: [0, 0, 0]}\n");
  EXPECT_EQ(loaded.section<dem::DemSection>("dem").grains.radius.front(), 0.003);
  const InputError error = load_error(listed + "    - {position: [0, 0, 0], radius: 0.001}\n");
  EXPECT_EQ(error.location().key_path, "dem.grains[0].radius");
  EXPECT_THAT(error.message(), HasSubstr("takes its size from species[].shape"));
}

}  // namespace
}  // namespace partimix::case_test
