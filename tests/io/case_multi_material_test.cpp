// sph.scheme: multi_material (docs/case-reference.md, "sph.materials", "sph.multi_material"): a
// case of three materials (a Redlich-Kwong gas, a Tait liquid, a Johnson-Cook solid) loads with
// its values and each region's material index; each bad key is an InputError naming its key path.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <limits>

#include "case_files.hpp"
#include "support/multi_material_case.hpp"
#include "support/sph_case.hpp"

namespace partimix::case_test {
namespace {

using test_support::multi_material_case;
using test_support::region_with;
using ::testing::HasSubstr;

const std::string kThreeMaterials = R"(solver: sph
dimensions: 2
domain:
  min: [0, 0]
  max: [1.0, 1.0]
time:
  end: 1.0e-3
  output_interval: 1.0e-4
sph:
  spacing: 0.01
  scheme: multi_material
  time_step:
    conductive: 0.05
    capillary: 0.2
  multi_material:
    density: summation
    eta: 1.3
    artificial_viscosity: {alpha: 0.5, beta: 1}
    ambient: {pressure: 101325, temperature: 1200, heat_transfer_coefficient: 50}
  materials:
    - name: vapour
      eos: {model: redlich_kwong, molar_mass: 0.17, a: 1.295, b: 4.9e-5}
      pressure: 1.0e7
      temperature: 288
      specific_heat: 1700
      conductivity: 0.03
      surface_heat_flux: 4.0e7
    - name: fuel
      eos: {model: tait, reference_density: 800, sound_speed: 50}
      specific_heat: 2000
      viscosity: 1.5e-3
      conductivity: 0.12
      surface_tension: 0.025
      heat_source: -10
    - name: shell
      eos: {model: tait, reference_density: 1000, sound_speed: 100, gamma: 3}
      density: 1010
      specific_heat: 1500
      solid:
        shear_modulus: 1.0e6
        artificial_stress: 0.2
        formulation: total_lagrangian
        hourglass: 0.5
        johnson_cook:
          A: 1.0e5
          B: 2.0e5
          n: 0.5
          C: 0.01
          m: 1.2
          reference_strain_rate: 10
          room_temperature: 293
          melt_temperature: 450
          D1: 0.3
          D2: 0.1
          D3: -1.5
          D4: 0.02
          D5: 0.5
          damage_threshold: 0.05
          critical_damage: 0.9
fluid:
  tracer: {}
  regions:
    - shape: box
      min: [0.4, 0.4]
      max: [0.6, 0.6]
      material: shell
    - shape: box
      min: [0, 0]
      max: [0.2, 0.2]
      material: vapour
    - shape: box
      min: [0.8, 0.8]
      max: [1.0, 1.0]
      material: fuel
)";

// A Tait liquid named `liquid` with only its required keys, an item of sph.materials.
const std::string kLiquid = R"(    - name: liquid
      eos: {model: tait, reference_density: 800, sound_speed: 50}
      specific_heat: 2000
)";

// A material named `name` of specific heat 1000 with the keys `keys` (lines indented as its keys).
std::string material(const std::string& name, const std::string& keys) {
  return "    - name: " + name + "\n      specific_heat: 1000\n" + keys;
}

// A Tait solid named `name` whose johnson_cook map holds `keys` (a flow map's content).
std::string solid(const std::string& name, const std::string& keys) {
  return material(name,
                  "      eos: {model: tait, reference_density: 1000, sound_speed: 100}\n"
                  "      solid:\n        shear_modulus: 1.0e6\n        johnson_cook: {" +
                      keys + "}\n");
}

// Loading `text` is an InputError at a line of the file naming `key_path`, whose message holds
// `words`.
void expect_error(const std::string& text, const std::string& key_path, const std::string& words) {
  const InputError error = load_error(text);
  EXPECT_EQ(error.location().key_path, key_path) << error.what();
  EXPECT_THAT(error.message(), HasSubstr(words)) << error.what();
  EXPECT_GT(error.location().line, 0) << error.what();
}

const sph::MultiMaterialSettings& settings_of(const io::Case& loaded) {
  return test_support::sph_config(loaded).multi_material;
}

TEST(CaseMultiMaterial, ThreeMaterialsLoadWithTheirSettings) {
  const io::Case loaded = load_text(kThreeMaterials);
  const sph::Config& config = test_support::sph_config(loaded);
  EXPECT_EQ(config.scheme, "multi_material");
  EXPECT_DOUBLE_EQ(config.time_step.conductive, 0.05);
  EXPECT_DOUBLE_EQ(config.time_step.capillary, 0.2);
  const sph::MultiMaterialSettings& settings = config.multi_material;
  EXPECT_EQ(settings.density, "summation");
  EXPECT_DOUBLE_EQ(settings.eta, 1.3);
  EXPECT_DOUBLE_EQ(settings.alpha, 0.5);
  EXPECT_DOUBLE_EQ(settings.beta, 1.0);
  EXPECT_DOUBLE_EQ(settings.ambient.pressure, 101325.0);
  EXPECT_DOUBLE_EQ(settings.ambient.temperature, 1200.0);
  EXPECT_DOUBLE_EQ(settings.ambient.heat_transfer_coefficient, 50.0);
  ASSERT_EQ(settings.materials.size(), 3u);
}

TEST(CaseMultiMaterial, RedlichKwongGasLoadsWithItsPressure) {
  const io::Case loaded = load_text(kThreeMaterials);
  const sph::MaterialSpec& gas = settings_of(loaded).materials[0];
  EXPECT_EQ(gas.name, "vapour");
  EXPECT_EQ(gas.eos.model, "redlich_kwong");
  EXPECT_DOUBLE_EQ(gas.eos.molar_mass, 0.17);
  EXPECT_DOUBLE_EQ(gas.eos.a, 1.295);
  EXPECT_DOUBLE_EQ(gas.eos.b, 4.9e-5);
  EXPECT_FALSE(gas.density.has_value());
  EXPECT_DOUBLE_EQ(gas.pressure.value(), 1.0e7);
  EXPECT_DOUBLE_EQ(gas.temperature, 288.0);
  EXPECT_DOUBLE_EQ(gas.specific_heat, 1700.0);
  EXPECT_DOUBLE_EQ(gas.conductivity, 0.03);
  EXPECT_DOUBLE_EQ(gas.viscosity, 0.0);
  EXPECT_DOUBLE_EQ(gas.surface_tension, 0.0);
  EXPECT_DOUBLE_EQ(gas.heat_source, 0.0);
  EXPECT_DOUBLE_EQ(gas.surface_heat_flux, 4.0e7);
  EXPECT_FALSE(gas.solid.has_value());
}

TEST(CaseMultiMaterial, TaitLiquidWithoutDensityStartsAtItsReferenceDensity) {
  const io::Case loaded = load_text(kThreeMaterials);
  const sph::MaterialSpec& liquid = settings_of(loaded).materials[1];
  EXPECT_EQ(liquid.name, "fuel");
  EXPECT_EQ(liquid.eos.model, "tait");
  EXPECT_DOUBLE_EQ(liquid.eos.reference_density, 800.0);
  EXPECT_DOUBLE_EQ(liquid.eos.sound_speed, 50.0);
  EXPECT_DOUBLE_EQ(liquid.eos.gamma, 7.0);
  EXPECT_DOUBLE_EQ(liquid.density.value(), 800.0);
  EXPECT_FALSE(liquid.pressure.has_value());
  EXPECT_DOUBLE_EQ(liquid.temperature, 293.15);
  EXPECT_DOUBLE_EQ(liquid.viscosity, 1.5e-3);
  EXPECT_DOUBLE_EQ(liquid.surface_tension, 0.025);
  EXPECT_DOUBLE_EQ(liquid.heat_source, -10.0);
  EXPECT_DOUBLE_EQ(liquid.surface_heat_flux, 0.0);
  EXPECT_FALSE(liquid.fixed_temperature);
  EXPECT_EQ(loaded.resolved["sph"]["materials"][1]["density"], 800.0);
}

TEST(CaseMultiMaterial, JohnsonCookSolidLoads) {
  const io::Case loaded = load_text(kThreeMaterials);
  const sph::MaterialSpec& shell = settings_of(loaded).materials[2];
  EXPECT_EQ(shell.name, "shell");
  EXPECT_DOUBLE_EQ(shell.eos.gamma, 3.0);
  EXPECT_DOUBLE_EQ(shell.density.value(), 1010.0);
  ASSERT_TRUE(shell.solid.has_value());
  EXPECT_DOUBLE_EQ(shell.solid->shear_modulus, 1.0e6);
  EXPECT_DOUBLE_EQ(shell.solid->artificial_stress, 0.2);
  EXPECT_TRUE(shell.solid->total_lagrangian);
  EXPECT_DOUBLE_EQ(shell.solid->hourglass, 0.5);
  const materials::JohnsonCookParameters& jc = shell.solid->johnson_cook;
  EXPECT_DOUBLE_EQ(jc.A, 1.0e5);
  EXPECT_DOUBLE_EQ(jc.B, 2.0e5);
  EXPECT_DOUBLE_EQ(jc.n, 0.5);
  EXPECT_DOUBLE_EQ(jc.C, 0.01);
  EXPECT_DOUBLE_EQ(jc.m, 1.2);
  EXPECT_DOUBLE_EQ(jc.reference_strain_rate, 10.0);
  EXPECT_DOUBLE_EQ(jc.room_temperature, 293.0);
  EXPECT_DOUBLE_EQ(jc.melt_temperature, 450.0);
  EXPECT_DOUBLE_EQ(jc.D1, 0.3);
  EXPECT_DOUBLE_EQ(jc.D2, 0.1);
  EXPECT_DOUBLE_EQ(jc.D3, -1.5);
  EXPECT_DOUBLE_EQ(jc.D4, 0.02);
  EXPECT_DOUBLE_EQ(jc.D5, 0.5);
  EXPECT_DOUBLE_EQ(jc.damage_threshold, 0.05);
  EXPECT_DOUBLE_EQ(jc.critical_damage, 0.9);
}

TEST(CaseMultiMaterial, RegionsNameTheirMaterials) {
  const io::Case loaded = load_text(kThreeMaterials);
  const sph::FluidSpec& fluid = test_support::fluid_of(loaded);
  ASSERT_EQ(fluid.regions.size(), 3u);
  EXPECT_EQ(fluid.regions[0].material, 2);
  EXPECT_EQ(fluid.regions[1].material, 0);
  EXPECT_EQ(fluid.regions[2].material, 1);
  EXPECT_TRUE(fluid.tracer.has_value());
}

TEST(CaseMultiMaterial, SchemeSettingsHaveDefaults) {
  const io::Case loaded = load_text(multi_material_case(kLiquid));
  const sph::Config& config = test_support::sph_config(loaded);
  EXPECT_DOUBLE_EQ(config.time_step.conductive, 0.1);
  EXPECT_DOUBLE_EQ(config.time_step.capillary, 0.25);
  const sph::MultiMaterialSettings& settings = config.multi_material;
  EXPECT_EQ(settings.density, "continuity");
  EXPECT_DOUBLE_EQ(settings.eta, 1.5);
  EXPECT_DOUBLE_EQ(settings.background_pressure, 0.0);
  EXPECT_DOUBLE_EQ(settings.alpha, 1.0);
  EXPECT_DOUBLE_EQ(settings.beta, 2.0);
  EXPECT_DOUBLE_EQ(settings.ambient.pressure, 0.0);
  EXPECT_DOUBLE_EQ(settings.ambient.temperature, 293.15);
  EXPECT_DOUBLE_EQ(settings.ambient.heat_transfer_coefficient, 0.0);
  EXPECT_EQ(loaded.resolved["sph"]["multi_material"]["ambient"]["temperature"], 293.15);
}

TEST(CaseMultiMaterial, SolidWithoutJohnsonCookIsElastic) {
  const std::string text = multi_material_case(
      material("liquid",
               "      eos: {model: tait, reference_density: 1000, sound_speed: 100}\n"
               "      solid: {shear_modulus: 1.0e6}\n"));
  const io::Case loaded = load_text(text);
  const sph::SolidSpec& solid = settings_of(loaded).materials[0].solid.value();
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  EXPECT_DOUBLE_EQ(solid.artificial_stress, 0.3);
  EXPECT_FALSE(solid.total_lagrangian);
  EXPECT_DOUBLE_EQ(solid.hourglass, 0.1);
  EXPECT_EQ(solid.johnson_cook.A, kInfinity);
  EXPECT_EQ(solid.johnson_cook.D1, kInfinity);
  EXPECT_EQ(solid.johnson_cook.melt_temperature, kInfinity);
}

TEST(CaseMultiMaterial, JohnsonCookHasDefaults) {
  const io::Case loaded = load_text(multi_material_case(solid("liquid", "")));
  const materials::JohnsonCookParameters& jc = settings_of(loaded).materials[0].solid->johnson_cook;
  const materials::JohnsonCookParameters defaults;
  EXPECT_DOUBLE_EQ(jc.A, defaults.A);
  EXPECT_DOUBLE_EQ(jc.n, defaults.n);
  EXPECT_DOUBLE_EQ(jc.room_temperature, defaults.room_temperature);
  EXPECT_DOUBLE_EQ(jc.melt_temperature, defaults.melt_temperature);
  EXPECT_DOUBLE_EQ(jc.critical_damage, defaults.critical_damage);
}

TEST(CaseMultiMaterial, UnknownEosModel) {
  const InputError error =
      load_error(multi_material_case(material("liquid", "      eos: {model: stiffened_gas}\n")));
  expect_location(error, "case.yaml", 15, 20, "sph.materials[0].eos.model");
  EXPECT_EQ(error.message(),
            "unknown value 'stiffened_gas'; expected one of: tait, ideal_gas, redlich_kwong");
}

TEST(CaseMultiMaterial, RedlichKwongWithoutB) {
  expect_error(
      multi_material_case(material("liquid",
                                   "      eos: {model: redlich_kwong, molar_mass: 0.17, a: 1.295}\n"
                                   "      pressure: 1.0e7\n")),
      "sph.materials[0].eos.b", "missing required key 'b'");
}

TEST(CaseMultiMaterial, TaitKeyOnAnIdealGas) {
  expect_error(multi_material_case(
                   material("liquid",
                            "      eos: {model: ideal_gas, molar_mass: 0.029, sound_speed: 340}\n"
                            "      pressure: 1.0e5\n")),
               "sph.materials[0].eos.sound_speed",
               "unknown key 'sound_speed'; expected one of: model, molar_mass");
}

TEST(CaseMultiMaterial, DensityAndPressureTogether) {
  expect_error(multi_material_case(kLiquid + "      density: 800\n      pressure: 1.0e5\n"),
               "sph.materials[0].pressure", "give either 'density' or 'pressure', not both");
}

TEST(CaseMultiMaterial, GasWithNeitherDensityNorPressure) {
  expect_error(
      multi_material_case(material("liquid", "      eos: {model: ideal_gas, molar_mass: 0.029}\n")),
      "sph.materials[0].density", "missing required key 'density' or 'pressure'");
}

TEST(CaseMultiMaterial, DuplicateNames) {
  expect_error(multi_material_case(kLiquid + kLiquid), "sph.materials[1].name",
               "'liquid' is already the name of sph.materials[0]");
}

TEST(CaseMultiMaterial, EmptyName) {
  expect_error(multi_material_case(material("\"\"", "")), "sph.materials[0].name",
               "must not be empty");
}

TEST(CaseMultiMaterial, MaterialsRequired) {
  expect_error(multi_material_case("    []\n"), "sph.materials", "at least one item");
}

TEST(CaseMultiMaterial, RegionOfAnUnknownMaterial) {
  const std::string materials =
      kLiquid + material("gas",
                         "      eos: {model: ideal_gas, molar_mass: 0.029}\n"
                         "      pressure: 1.0e5\n");
  expect_error(multi_material_case(materials, region_with("      material: water\n")),
               "fluid.regions[0].material", "unknown value 'water'; expected one of: liquid, gas");
}

TEST(CaseMultiMaterial, RegionWithoutMaterial) {
  expect_error(multi_material_case(kLiquid, region_with("")), "fluid.regions[0].material",
               "missing required key 'material'");
}

TEST(CaseMultiMaterial, FluidDensityIsNotAllowed) {
  expect_error(
      multi_material_case(kLiquid, "  density: 1000\n" + region_with("      material: liquid\n")),
      "fluid.density", "not with sph.scheme: multi_material");
}

TEST(CaseMultiMaterial, FluidViscosityIsNotAllowed) {
  expect_error(multi_material_case(
                   kLiquid, "  viscosity: 1.0e-3\n" + region_with("      material: liquid\n")),
               "fluid.viscosity", "each of sph.materials has its own density and viscosity");
}

TEST(CaseMultiMaterial, MaterialsNeedTheScheme) {
  const std::string text = insert_line(kMinimal2D, 11, "  materials: []");
  expect_error(text, "sph.materials",
               "only with scheme: multi_material (the scheme is weakly_compressible)");
}

TEST(CaseMultiMaterial, MultiMaterialSettingsNeedTheScheme) {
  const std::string text = insert_line(kMinimal2D, 11, "  multi_material: {eta: 1.2}");
  expect_error(text, "sph.multi_material", "only with scheme: multi_material");
}

TEST(CaseMultiMaterial, RegionMaterialNeedsTheScheme) {
  expect_error(kMinimal2D + "      material: liquid\n", "fluid.regions[0].material",
               "only with sph.scheme: multi_material (the scheme is weakly_compressible)");
}

TEST(CaseMultiMaterial, MeltNotAboveRoomTemperature) {
  expect_error(multi_material_case(solid("liquid", "room_temperature: 400, melt_temperature: 400")),
               "sph.materials[0].solid.johnson_cook.melt_temperature",
               "must be > room_temperature (400), got 400");
}

TEST(CaseMultiMaterial, CriticalDamageZero) {
  expect_error(multi_material_case(solid("liquid", "critical_damage: 0")),
               "sph.materials[0].solid.johnson_cook.critical_damage", "must be > 0, got 0");
}

TEST(CaseMultiMaterial, CriticalDamageAboveOne) {
  expect_error(multi_material_case(solid("liquid", "critical_damage: 1.5")),
               "sph.materials[0].solid.johnson_cook.critical_damage", "must be <= 1, got 1.5");
}

TEST(CaseMultiMaterial, SolidNeedsShearModulus) {
  expect_error(multi_material_case(kLiquid + "      solid: {artificial_stress: 0.3}\n"),
               "sph.materials[0].solid.shear_modulus", "missing required key 'shear_modulus'");
}

TEST(CaseMultiMaterial, UnknownSolidFormulation) {
  expect_error(
      multi_material_case(kLiquid + "      solid: {shear_modulus: 1.0e6, formulation: eulerian}\n"),
      "sph.materials[0].solid.formulation", "total_lagrangian");
}

TEST(CaseMultiMaterial, NegativeHourglass) {
  expect_error(
      multi_material_case(kLiquid + "      solid: {shear_modulus: 1.0e6, hourglass: -1}\n"),
      "sph.materials[0].solid.hourglass", "must be >= 0, got -1");
}

TEST(CaseMultiMaterial, AFixedTemperatureLoads) {
  const io::Case loaded =
      load_text(multi_material_case(kLiquid + "      fixed_temperature: true\n"));
  EXPECT_TRUE(settings_of(loaded).materials[0].fixed_temperature);
}

// docs/multi-material-sph.md, "Heat conduction": a held temperature takes no heating.
TEST(CaseMultiMaterial, AFixedTemperatureTakesNoHeatSource) {
  expect_error(
      multi_material_case(kLiquid + "      fixed_temperature: true\n      heat_source: 5\n"),
      "sph.materials[0].fixed_temperature", "takes no heat_source");
}

TEST(CaseMultiMaterial, TimeStepFactorsArePositive) {
  const std::string text = insert_line(kMinimal2D, 11, "  time_step: {capillary: 0}");
  expect_error(text, "sph.time_step.capillary", "must be > 0, got 0");
}

}  // namespace
}  // namespace partimix::case_test
