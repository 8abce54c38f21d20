// fluid.viscosity (Newtonian) or fluid.rheology (any model of materials/rheology.hpp): each model
// loads with its keys and defaults, and each bad rheology is an InputError naming file, line,
// column and key path.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <limits>

#include "case_files.hpp"
#include "support/sph_case.hpp"

namespace partimix::case_test {
namespace {

using ::testing::HasSubstr;

constexpr int kRheologyLine = 13;  // the line of `viscosity:` in kMinimal2D

// kMinimal2D with `fluid.viscosity` replaced by a `rheology` map holding `keys` ("key: value"),
// the first on line kRheologyLine + 1.
std::string with_rheology(const std::vector<std::string>& keys) {
  std::string text = replace_line(kMinimal2D, kRheologyLine, "  rheology:");
  for (std::size_t i = 0; i < keys.size(); ++i) {
    text = insert_line(text, kRheologyLine + 1 + i, "    " + keys[i]);
  }
  return text;
}

materials::RheologyConfig load_rheology(const std::vector<std::string>& keys) {
  return test_support::fluid_of(load_text(with_rheology(keys))).rheology;
}

// The InputError that loading a rheology map of `keys` throws.
InputError rheology_error(const std::vector<std::string>& keys) {
  return load_error(with_rheology(keys));
}

// The line of keys[index] in with_rheology(keys).
int line_of_key(std::size_t index) {
  return kRheologyLine + 1 + static_cast<int>(index);
}

TEST(CaseRheology, ViscosityKeyLoadsAsNewtonian) {
  const io::Case loaded = load_text(kMinimal2D);
  EXPECT_EQ(test_support::fluid_of(loaded).rheology.model, "newtonian");
  EXPECT_DOUBLE_EQ(test_support::fluid_of(loaded).rheology.viscosity, 1.0e-3);
  EXPECT_DOUBLE_EQ(test_support::fluid_of(loaded).rheology.viscosity, 1.0e-3);
  EXPECT_EQ(test_support::fluid_of(loaded).rheology.viscosity_max,
            std::numeric_limits<double>::infinity());
  EXPECT_EQ(loaded.resolved["fluid"]["viscosity"], 1.0e-3);
  EXPECT_FALSE(loaded.resolved["fluid"].contains("rheology"));
}

TEST(CaseRheology, NewtonianMapLoads) {
  const io::Case loaded = load_text(with_rheology({"model: newtonian", "viscosity: 0.5"}));
  EXPECT_EQ(test_support::fluid_of(loaded).rheology.model, "newtonian");
  EXPECT_DOUBLE_EQ(test_support::fluid_of(loaded).rheology.viscosity, 0.5);
  EXPECT_DOUBLE_EQ(test_support::fluid_of(loaded).rheology.viscosity, 0.5);
}

TEST(CaseRheology, PowerLawLoads) {
  const io::Case loaded = load_text(with_rheology(
      {"model: power_law", "consistency: 13.9", "flow_index: 0.47", "viscosity_max: 1.0e4"}));
  const materials::RheologyConfig& c = test_support::fluid_of(loaded).rheology;
  EXPECT_EQ(c.model, "power_law");
  EXPECT_DOUBLE_EQ(c.consistency, 13.9);
  EXPECT_DOUBLE_EQ(c.flow_index, 0.47);
  EXPECT_DOUBLE_EQ(c.viscosity_min, 0.0);
  EXPECT_DOUBLE_EQ(c.viscosity_max, 1.0e4);
  EXPECT_DOUBLE_EQ(test_support::fluid_of(loaded).rheology.viscosity, 0.0);
}

TEST(CaseRheology, HerschelBulkleyLoadsWithPapanastasiouByDefault) {
  const materials::RheologyConfig c = load_rheology(
      {"model: herschel_bulkley", "yield_stress: 5", "consistency: 2", "flow_index: 1"});
  EXPECT_EQ(c.model, "herschel_bulkley");
  EXPECT_DOUBLE_EQ(c.yield_stress, 5.0);
  EXPECT_DOUBLE_EQ(c.consistency, 2.0);
  EXPECT_DOUBLE_EQ(c.flow_index, 1.0);
  EXPECT_EQ(c.regularisation, "papanastasiou");
  EXPECT_DOUBLE_EQ(c.papanastasiou_exponent, 1000.0);
  EXPECT_EQ(c.viscosity_max, std::numeric_limits<double>::infinity());
}

TEST(CaseRheology, BinghamLoadsWithBiviscousAndBounds) {
  const materials::RheologyConfig c =
      load_rheology({"model: bingham", "yield_stress: 5", "plastic_viscosity: 0.1",
                     "regularisation: biviscous", "viscosity_min: 0.01", "viscosity_max: 100"});
  EXPECT_EQ(c.model, "bingham");
  EXPECT_DOUBLE_EQ(c.yield_stress, 5.0);
  EXPECT_DOUBLE_EQ(c.plastic_viscosity, 0.1);
  EXPECT_EQ(c.regularisation, "biviscous");
  EXPECT_DOUBLE_EQ(c.viscosity_min, 0.01);
  EXPECT_DOUBLE_EQ(c.viscosity_max, 100.0);
}

TEST(CaseRheology, CrossLoads) {
  const materials::RheologyConfig c =
      load_rheology({"model: cross", "zero_shear_viscosity: 10", "infinite_shear_viscosity: 0.01",
                     "time_constant: 0.5", "flow_index: 0.8"});
  EXPECT_EQ(c.model, "cross");
  EXPECT_DOUBLE_EQ(c.zero_shear_viscosity, 10.0);
  EXPECT_DOUBLE_EQ(c.infinite_shear_viscosity, 0.01);
  EXPECT_DOUBLE_EQ(c.time_constant, 0.5);
  EXPECT_DOUBLE_EQ(c.flow_index, 0.8);
}

TEST(CaseRheology, CarreauLoadsWithYasudaExponentTwoByDefault) {
  const std::vector<std::string> keys{"model: carreau", "zero_shear_viscosity: 10",
                                      "infinite_shear_viscosity: 0", "time_constant: 0.5",
                                      "flow_index: 0.4"};
  EXPECT_DOUBLE_EQ(load_rheology(keys).yasuda_exponent, 2.0);
  std::vector<std::string> yasuda = keys;
  yasuda.push_back("yasuda_exponent: 1.5");
  EXPECT_DOUBLE_EQ(load_rheology(yasuda).yasuda_exponent, 1.5);
}

TEST(CaseRheology, ResolvedShowsTheRheologyKeysUsed) {
  const nlohmann::json resolved =
      load_text(with_rheology({"model: bingham", "yield_stress: 5", "plastic_viscosity: 0.1"}))
          .resolved["fluid"]["rheology"];
  const nlohmann::json expected = {{"model", "bingham"},
                                   {"yield_stress", 5.0},
                                   {"plastic_viscosity", 0.1},
                                   {"regularisation", "papanastasiou"},
                                   {"papanastasiou_exponent", 1000.0},
                                   {"viscosity_min", 0.0},
                                   {"viscosity_max", "auto"}};
  EXPECT_EQ(resolved, expected);
}

TEST(CaseRheology, NonPositiveFlowIndex) {
  const InputError error =
      rheology_error({"model: power_law", "consistency: 13.9", "flow_index: 0"});
  expect_location(error, "case.yaml", line_of_key(2), 17, "fluid.rheology.flow_index");
  EXPECT_EQ(error.message(), "must be > 0, got 0");
}

TEST(CaseRheology, NonPositiveConsistency) {
  const InputError error =
      rheology_error({"model: herschel_bulkley", "yield_stress: 1", "consistency: -2"});
  expect_location(error, "case.yaml", line_of_key(2), 18, "fluid.rheology.consistency");
  EXPECT_EQ(error.message(), "must be > 0, got -2");
}

TEST(CaseRheology, NegativeYieldStress) {
  const InputError error = rheology_error({"model: bingham", "yield_stress: -1"});
  expect_location(error, "case.yaml", line_of_key(1), 19, "fluid.rheology.yield_stress");
  EXPECT_EQ(error.message(), "must be >= 0, got -1");
}

TEST(CaseRheology, ViscosityMaxNotAboveViscosityMin) {
  const InputError error =
      rheology_error({"model: newtonian", "viscosity: 1", "viscosity_min: 2", "viscosity_max: 2"});
  expect_location(error, "case.yaml", line_of_key(3), 20, "fluid.rheology.viscosity_max");
  EXPECT_EQ(error.message(), "must be > viscosity_min (2), got 2");
}

TEST(CaseRheology, InfiniteShearViscosityNotBelowZeroShear) {
  const InputError error =
      rheology_error({"model: cross", "zero_shear_viscosity: 1", "infinite_shear_viscosity: 1"});
  expect_location(error, "case.yaml", line_of_key(2), 31,
                  "fluid.rheology.infinite_shear_viscosity");
  EXPECT_EQ(error.message(), "must be < zero_shear_viscosity (1), got 1");
}

TEST(CaseRheology, ShearThinningPowerLawNeedsViscosityMax) {
  const InputError error =
      rheology_error({"model: power_law", "consistency: 13.9", "flow_index: 0.47"});
  expect_location(error, "case.yaml", line_of_key(0), 5, "fluid.rheology.viscosity_max");
  EXPECT_THAT(error.message(), HasSubstr("required for model power_law: with flow_index 0.47 < 1"));
  EXPECT_THAT(error.message(), HasSubstr("viscous time step"));
}

TEST(CaseRheology, ShearThickeningNeedsViscosityMax) {
  const InputError error = rheology_error(
      {"model: herschel_bulkley", "yield_stress: 1", "consistency: 2", "flow_index: 1.5"});
  EXPECT_EQ(error.location().key_path, "fluid.rheology.viscosity_max");
  EXPECT_THAT(error.message(), HasSubstr("flow_index 1.5 > 1 (shear thickening)"));
}

TEST(CaseRheology, BiviscousNeedsViscosityMax) {
  const InputError error = rheology_error(
      {"model: bingham", "yield_stress: 5", "plastic_viscosity: 0.1", "regularisation: biviscous"});
  EXPECT_EQ(error.location().key_path, "fluid.rheology.viscosity_max");
  EXPECT_THAT(error.message(), HasSubstr("regularisation biviscous"));
}

TEST(CaseRheology, KeyOfAnotherModelIsUnknown) {
  const InputError error =
      rheology_error({"model: power_law", "consistency: 2", "flow_index: 1", "yield_stress: 5"});
  expect_location(error, "case.yaml", line_of_key(3), 5, "fluid.rheology.yield_stress");
  EXPECT_EQ(error.message(),
            "unknown key 'yield_stress'; expected one of: model, consistency, flow_index, "
            "viscosity_min, viscosity_max");
}

TEST(CaseRheology, RegularisationOnlyForYieldStressModels) {
  const InputError error =
      rheology_error({"model: newtonian", "viscosity: 1", "regularisation: biviscous"});
  EXPECT_EQ(error.location().key_path, "fluid.rheology.regularisation");
  EXPECT_THAT(error.message(), HasSubstr("unknown key 'regularisation'"));
}

TEST(CaseRheology, PapanastasiouExponentOnlyWithPapanastasiou) {
  const InputError error = rheology_error({"model: bingham", "yield_stress: 5",
                                           "plastic_viscosity: 0.1", "regularisation: biviscous",
                                           "papanastasiou_exponent: 100", "viscosity_max: 100"});
  EXPECT_EQ(error.location().key_path, "fluid.rheology.papanastasiou_exponent");
  EXPECT_THAT(error.message(), HasSubstr("unknown key 'papanastasiou_exponent'"));
}

TEST(CaseRheology, ViscosityAndRheologyTogether) {
  const std::string text = insert_line(with_rheology({"model: newtonian", "viscosity: 1"}),
                                       kRheologyLine, "  viscosity: 1.0e-3");
  const InputError error = load_error(text);
  expect_location(error, "case.yaml", kRheologyLine + 2, 5, "fluid.rheology");
  EXPECT_EQ(error.message(), "give either 'viscosity' (a Newtonian fluid) or 'rheology', not both");
}

TEST(CaseRheology, NeitherViscosityNorRheology) {
  const InputError error = load_error(remove_line(kMinimal2D, kRheologyLine));
  expect_location(error, "case.yaml", 12, 3, "fluid.viscosity");
  EXPECT_THAT(error.message(), HasSubstr("'viscosity' (a Newtonian fluid) or 'rheology'"));
}

TEST(CaseRheology, UnknownModel) {
  const InputError error = rheology_error({"model: maxwell"});
  expect_location(error, "case.yaml", line_of_key(0), 12, "fluid.rheology.model");
  EXPECT_EQ(error.message(),
            "unknown value 'maxwell'; expected one of: newtonian, power_law, herschel_bulkley, "
            "bingham, cross, carreau");
}

TEST(CaseRheology, OverriddenFlowIndexNamesSet) {
  const InputError error =
      load_error(with_rheology({"model: power_law", "consistency: 2", "flow_index: 1"}),
                 {"fluid.rheology.flow_index=-1"});
  expect_location(error, "--set", 0, 0, "fluid.rheology.flow_index");
}

}  // namespace
}  // namespace partimix::case_test
