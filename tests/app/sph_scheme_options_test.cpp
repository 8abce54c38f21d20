// Settings of the incompressible scheme (docs/case-reference.md, `sph`): implicit viscosity with
// the weakly-compressible scheme is an input error naming the key; on `auto` implicit viscosity
// takes the stress form for a non-Newtonian fluid; a failed solve stops the run.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "app/simulation.hpp"
#include "core/error.hpp"
#include "sph/sph_solver.hpp"
#include "validation/case_factory.hpp"

namespace partimix {
namespace {

using ::testing::HasSubstr;

void expect_input_error(const io::Case& c, const std::string& key, const std::string& words) {
  try {
    app::build_simulation(c);
    ADD_FAILURE() << "expected an InputError naming " << key;
  } catch (const InputError& error) {
    EXPECT_EQ(error.location().key_path, key);
    EXPECT_THAT(error.message(), HasSubstr(words));
  }
}

TEST(SphSchemeOptions, ImplicitViscosityNeedsTheIncompressibleScheme) {
  io::Case c = testing_cases::tank_2d(0.2, 0.1, 0.01);
  testing_cases::sph_of(c).config.viscosity_integration = "implicit";
  expect_input_error(c, "sph.viscosity_integration", "sph.scheme: incompressible");
}

// Implicit viscosity keeps the stress form for a fluid whose viscosity varies: the Morris part
// implicit, div(eta G^T) explicit (docs/sph.md, "Implicit viscosity"); the Morris operator alone
// left that term out and turned a shear-thinning plate's torque 16% high.
TEST(SphSchemeOptions, ImplicitViscosityTakesTheStressFormForANonNewtonianFluidOnAuto) {
  io::Case c = testing_cases::tank_2d(0.2, 0.1, 0.01);
  sph::SphSection& sph = testing_cases::sph_of(c);
  sph.config.scheme = "incompressible";
  sph.config.viscosity_integration = "implicit";
  sph.fluid.rheology.model = "power_law";
  sph.fluid.rheology.consistency = 1.0;
  sph.fluid.rheology.flow_index = 0.5;
  const app::Simulation sim = app::build_simulation(c);
  const auto& solver = dynamic_cast<const sph::SphSolver&>(*sim.methods[0].solver);
  EXPECT_EQ(solver.parameters().viscous_operator, sph::ViscousOperator::stress);
}

// A pressure solve that cannot converge within the iterations allowed stops the run with its
// residual (the run loop then keeps the last good output).
// The tank has several thousand unknowns: below 500 the multigrid preconditioner is a direct
// solve, and one iteration would converge.
TEST(SphSchemeOptions, APressureSolveThatDoesNotConvergeStopsTheRun) {
  io::Case c = testing_cases::tank_2d(0.4, 0.2, 0.005);
  sph::Config& config = testing_cases::sph_of(c).config;
  config.scheme = "incompressible";
  config.pressure_iterations = 1;
  config.pressure_tolerance = 1e-14;
  app::Simulation sim = app::build_simulation(c);
  try {
    sim.methods[0].solver->step(sim.methods[0].solver->stable_dt());
    ADD_FAILURE() << "expected a RunError";
  } catch (const RunError& error) {
    EXPECT_THAT(error.what(), HasSubstr("the pressure Poisson equation did not converge"));
    EXPECT_THAT(error.what(), HasSubstr("sph.pressure_iterations 1"));
  }
}

}  // namespace
}  // namespace partimix
