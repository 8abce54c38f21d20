// Valid case files load with the values written and the documented defaults.
#include <gtest/gtest.h>

#include "case_files.hpp"
#include "support/sph_case.hpp"

namespace partimix::case_test {
namespace {

using io::Case;

const std::string kFull2D = R"(name: dam_break_2d
description: "A column of water collapses."
solver: sph
dimensions: 2
gravity: [0, -9.81]
domain:
  min: [-0.1, -0.1]
  max: [1.7, 1.1]
  periodic: [x]
time:
  end: 1.5
  output_interval: 0.02
  sample_interval: 0.005
sph:
  spacing: 0.01
  smoothing_ratio: 1.2
  kernel: cubic_spline
  gradient_kernel: hyperbolic
  equation_of_state: linear
  tait_gamma: 5
  sound_speed: 40
  max_velocity: 4.5
  mach_factor: 12
  flow_length: 0.02
  scheme: incompressible
  pressure_tolerance: 1.0e-8
  pressure_iterations: 300
  viscosity_integration: implicit
  viscosity_iterations: 4
  artificial_viscosity: 0.02
  laminar_viscosity: false
  viscous_operator: stress
  viscosity_mean: harmonic
  density:
    diffusion: molteni
    delta: 0.2
    shepard_interval: 30
  wall_layers: 4
  negative_wall_pressure: true
  time_step:
    cfl: 0.3
    flow_cfl: 0.05
    viscous: 0.1
    force: 0.2
  sort_interval: 10
fluid:
  density: 998.2
  viscosity: 1.0e-3
  regions:
    - shape: box
      min: [0, 0]
      max: [0.5, 1.0]
walls:
  - shape: box
    min: [0, 0]
    max: [1.6, 1.0]
    open: [y+]
output:
  frames: false
analyses:
  - type: front_position
    axis: y
)";

const std::string kCylinder3D = R"(solver: sph
dimensions: 3
gravity: [0, 0, -9.81]
domain:
  min: [-0.2, -0.2, -0.05]
  max: [0.2, 0.2, 0.4]
time:
  end: 0.5
  output_interval: 0.05
sph:
  spacing: 0.005
fluid:
  density: 1000
  viscosity: 1.0e-3
  regions:
    - shape: cylinder
      center: [0, 0, 0]
      radius: 0.15
      height: 0.3
walls:
  - shape: cylinder
    center: [0, 0, 0]
    radius: 0.15
    height: 0.35
    open: [z+]
analyses:
  - type: front_position
)";

TEST(CaseLoader, Full2DCaseHasTheValuesWritten) {
  const Case loaded = load_text(kFull2D);
  EXPECT_EQ(loaded.name, "dam_break_2d");
  EXPECT_EQ(loaded.description, "A column of water collapses.");
  ASSERT_EQ(loaded.methods.size(), 1u);
  EXPECT_EQ(loaded.methods[0].name, "sph");
  EXPECT_EQ(loaded.domain.dimensions, 2);
  EXPECT_EQ(loaded.gravity, Vec3(0.0, -9.81, 0.0));
  EXPECT_EQ(loaded.domain.lo, Vec3(-0.1, -0.1, 0.0));
  EXPECT_EQ(loaded.domain.hi, Vec3(1.7, 1.1, 0.0));
  EXPECT_TRUE(loaded.domain.periodic[0]);
  EXPECT_FALSE(loaded.domain.periodic[1]);
  EXPECT_DOUBLE_EQ(loaded.time.end, 1.5);
  EXPECT_DOUBLE_EQ(loaded.time.output_interval, 0.02);
  EXPECT_DOUBLE_EQ(loaded.time.sample_interval, 0.005);
  EXPECT_DOUBLE_EQ(test_support::fluid_of(loaded).density, 998.2);
  EXPECT_DOUBLE_EQ(test_support::fluid_of(loaded).rheology.viscosity, 1.0e-3);
  EXPECT_FALSE(loaded.output.frames);
  ASSERT_EQ(loaded.analyses.size(), 1u);
  EXPECT_EQ(loaded.analyses[0].type, "front_position");
  EXPECT_EQ(loaded.analyses[0].axis, 1);
}

TEST(CaseLoader, Full2DCaseHasTheSphSettingsWritten) {
  const sph::Config sph = test_support::sph_config(load_text(kFull2D));
  EXPECT_DOUBLE_EQ(sph.spacing, 0.01);
  EXPECT_DOUBLE_EQ(sph.smoothing_ratio, 1.2);
  EXPECT_EQ(sph.kernel, "cubic_spline");
  EXPECT_EQ(sph.gradient_kernel, "hyperbolic");
  EXPECT_EQ(sph.equation_of_state, "linear");
  EXPECT_DOUBLE_EQ(sph.tait_gamma, 5.0);
  EXPECT_EQ(sph.sound_speed, 40.0);
  EXPECT_EQ(sph.max_velocity, 4.5);
  EXPECT_DOUBLE_EQ(sph.mach_factor, 12.0);
  EXPECT_EQ(sph.flow_length, 0.02);
  EXPECT_EQ(sph.scheme, "incompressible");
  EXPECT_DOUBLE_EQ(sph.pressure_tolerance, 1.0e-8);
  EXPECT_EQ(sph.pressure_iterations, 300);
  EXPECT_EQ(sph.viscosity_integration, "implicit");
  EXPECT_EQ(sph.viscosity_iterations, 4);
  EXPECT_DOUBLE_EQ(sph.artificial_viscosity, 0.02);
  EXPECT_FALSE(sph.laminar_viscosity);
  EXPECT_EQ(sph.viscous_operator, "stress");
  EXPECT_EQ(sph.viscosity_mean, "harmonic");
  EXPECT_EQ(sph.density.diffusion, "molteni");
  EXPECT_DOUBLE_EQ(sph.density.delta, 0.2);
  EXPECT_EQ(sph.density.shepard_interval, 30);
  EXPECT_EQ(sph.wall_layers, 4);
  EXPECT_TRUE(sph.negative_wall_pressure);
  EXPECT_DOUBLE_EQ(sph.time_step.cfl, 0.3);
  EXPECT_DOUBLE_EQ(sph.time_step.flow_cfl, 0.05);
  EXPECT_DOUBLE_EQ(sph.time_step.viscous, 0.1);
  EXPECT_DOUBLE_EQ(sph.time_step.force, 0.2);
  EXPECT_EQ(sph.sort_interval, 10);
}

TEST(CaseLoader, SmoothingLengthIsConstantUnlessAskedToVary) {
  EXPECT_FALSE(test_support::sph_config(load_text(kMinimal2D)).variable_smoothing_length);
  const std::string variable = insert_line(kMinimal2D, 11, "  smoothing_length: variable");
  EXPECT_TRUE(test_support::sph_config(load_text(variable)).variable_smoothing_length);
}

TEST(CaseLoader, TwoDimensionalBoxesSpanZFromMinusOneToOne) {
  const Case loaded = load_text(kFull2D);
  ASSERT_EQ(test_support::fluid_of(loaded).regions.size(), 1u);
  EXPECT_EQ(test_support::fluid_of(loaded).regions[0].shape->lower(), Vec3(0.0, 0.0, -1.0));
  EXPECT_EQ(test_support::fluid_of(loaded).regions[0].shape->upper(), Vec3(0.5, 1.0, 1.0));
  EXPECT_LT(test_support::fluid_of(loaded).regions[0].shape->signed_distance(Vec3(0.25, 0.5, 0.0)),
            0.0);
}

TEST(CaseLoader, WallOpenFacesBecomeFaces) {
  const Case loaded = load_text(kFull2D);
  ASSERT_EQ(loaded.walls.size(), 1u);
  ASSERT_EQ(loaded.walls[0].open_faces.size(), 1u);
  EXPECT_EQ(loaded.walls[0].open_faces[0].axis, 1);
  EXPECT_EQ(loaded.walls[0].open_faces[0].side, 1);
}

TEST(CaseLoader, MinimalCaseTakesTheDefaults) {
  const Case loaded = load_text(kMinimal2D);
  EXPECT_EQ(loaded.name, "case");
  EXPECT_EQ(loaded.description, "");
  EXPECT_EQ(loaded.gravity, Vec3::Zero());
  EXPECT_FALSE(loaded.domain.periodic[0] || loaded.domain.periodic[1]);
  EXPECT_DOUBLE_EQ(loaded.time.sample_interval, 0.02);
  EXPECT_TRUE(loaded.walls.empty());
  EXPECT_TRUE(loaded.output.frames);
  EXPECT_TRUE(loaded.analyses.empty());
  const sph::Config defaults;
  EXPECT_DOUBLE_EQ(test_support::sph_config(loaded).smoothing_ratio, defaults.smoothing_ratio);
  EXPECT_EQ(test_support::sph_config(loaded).kernel, defaults.kernel);
  EXPECT_EQ(test_support::sph_config(loaded).gradient_kernel, "");
  EXPECT_EQ(test_support::sph_config(loaded).equation_of_state, "tait");
  EXPECT_FALSE(test_support::sph_config(loaded).sound_speed.has_value());
  EXPECT_FALSE(test_support::sph_config(loaded).max_velocity.has_value());
  EXPECT_FALSE(test_support::sph_config(loaded).wall_layers.has_value());
  EXPECT_FALSE(test_support::sph_config(loaded).negative_wall_pressure);
  EXPECT_EQ(test_support::sph_config(loaded).density.diffusion, "fourtakas");
  EXPECT_EQ(test_support::sph_config(loaded).sort_interval, 20);
  EXPECT_EQ(test_support::sph_config(loaded).viscous_operator, "auto");
  EXPECT_EQ(test_support::sph_config(loaded).viscosity_mean, "arithmetic");
  EXPECT_FALSE(test_support::sph_config(loaded).polar_centre.has_value());
  EXPECT_FALSE(test_support::sph_config(loaded).golden_rings);
}

TEST(CaseLoader, PolarLatticeTakesItsCentreAndRings) {
  std::string text = kMinimal2D;
  const std::string spacing = "  spacing: 0.01\n";
  text.insert(text.find(spacing) + spacing.size(),
              "  lattice: {type: polar, centre: [0.8, 0.5], rings: golden}\n");
  const Case loaded = load_text(text);
  const sph::Config& config = test_support::sph_config(loaded);
  EXPECT_EQ(config.polar_centre, Vec3(0.8, 0.5, 0.0));
  EXPECT_TRUE(config.golden_rings);
}

TEST(CaseLoader, ThreeDimensionalCylinderCase) {
  const Case loaded = load_text(kCylinder3D);
  EXPECT_EQ(loaded.domain.dimensions, 3);
  EXPECT_EQ(loaded.gravity, Vec3(0.0, 0.0, -9.81));
  ASSERT_EQ(test_support::fluid_of(loaded).regions.size(), 1u);
  const geometry::Shape& region = *test_support::fluid_of(loaded).regions[0].shape;
  EXPECT_EQ(region.lower(), Vec3(-0.15, -0.15, 0.0));
  EXPECT_EQ(region.upper(), Vec3(0.15, 0.15, 0.3));
  ASSERT_EQ(loaded.walls.size(), 1u);
  ASSERT_EQ(loaded.walls[0].open_faces.size(), 1u);
  EXPECT_EQ(loaded.walls[0].open_faces[0].axis, 2);
  EXPECT_EQ(loaded.walls[0].open_faces[0].side, 1);
  ASSERT_EQ(loaded.analyses.size(), 1u);
  EXPECT_EQ(loaded.analyses[0].axis, 0);
}

TEST(CaseLoader, ResolvedHoldsEveryKeyWithDefaults) {
  const nlohmann::json resolved = load_text(kMinimal2D).resolved;
  EXPECT_EQ(resolved["name"], "case");
  EXPECT_EQ(resolved["dimensions"], 2);
  EXPECT_EQ(resolved["gravity"], nlohmann::json::array({0.0, 0.0}));
  EXPECT_EQ(resolved["domain"]["max"], nlohmann::json::array({1.6, 1.0}));
  EXPECT_EQ(resolved["domain"]["periodic"], nlohmann::json::array());
  EXPECT_EQ(resolved["time"]["sample_interval"], 0.02);
  EXPECT_EQ(resolved["sph"]["smoothing_ratio"], sph::Config().smoothing_ratio);
  EXPECT_EQ(resolved["sph"]["gradient_kernel"], "same");
  EXPECT_EQ(resolved["sph"]["sound_speed"], "auto");
  EXPECT_EQ(resolved["sph"]["wall_layers"], "auto");
  EXPECT_EQ(resolved["sph"]["density"]["delta"], 0.1);
  EXPECT_EQ(resolved["sph"]["time_step"]["cfl"], 0.2);
  EXPECT_EQ(resolved["fluid"]["regions"][0]["shape"], "box");
  EXPECT_EQ(resolved["fluid"]["regions"][0]["max"], nlohmann::json::array({0.5, 1.0}));
  EXPECT_EQ(resolved["walls"], nlohmann::json::array());
  EXPECT_EQ(resolved["output"]["frames"], true);
  EXPECT_EQ(resolved["analyses"], nlohmann::json::array());
}

TEST(CaseLoader, ResolvedHoldsNumbersGivenForAutoKeys) {
  const nlohmann::json resolved = load_text(kFull2D).resolved;
  EXPECT_EQ(resolved["sph"]["sound_speed"], 40.0);
  EXPECT_EQ(resolved["sph"]["wall_layers"], 4);
  EXPECT_EQ(resolved["walls"][0]["open"], nlohmann::json::array({"y+"}));
  EXPECT_EQ(resolved["analyses"][0]["axis"], "y");
}

TEST(CaseLoader, EmptyOptionalSectionsTakeTheDefaults) {
  const Case loaded = load_text(kMinimal2D + "walls:\noutput:\nanalyses: []\n");
  EXPECT_TRUE(loaded.walls.empty());
  EXPECT_TRUE(loaded.output.frames);
}

}  // namespace
}  // namespace partimix::case_test
