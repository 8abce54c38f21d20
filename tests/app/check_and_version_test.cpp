// `partimix check`, `--version`, `--help`, and a command line without a sub-command.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "cli_support.hpp"
#include "dam_break_case.hpp"
#include "support/temp_dir.hpp"

namespace partimix::cli_test {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;

TEST(CheckCommand, ValidCaseExitsZeroAndWritesNothing) {
  const Scratch scratch;
  scratch.write("case.yaml", kDamBreak3D);
  const Outcome outcome = run_partimix(scratch, {"check", "case.yaml"});
  EXPECT_EQ(outcome.exit_code, 0) << outcome.err;
  EXPECT_THAT(outcome.err, HasSubstr("case.yaml: valid ("));
  EXPECT_THAT(scratch.work_entries(), ElementsAre("case.yaml"));
}

TEST(CheckCommand, BadSetExitsTwoAndWritesNothing) {
  const Scratch scratch;
  scratch.write("case.yaml", kDamBreak3D);
  const Outcome outcome = run_partimix(scratch, {"check", "case.yaml", "--set", "sph.spacing=0"});
  EXPECT_EQ(outcome.exit_code, 2) << outcome.err;
  EXPECT_THAT(outcome.err, HasSubstr("error: --set: sph.spacing: "));
  EXPECT_THAT(scratch.work_entries(), ElementsAre("case.yaml"));
}

// cases/cfdem_centrifuge.yaml as case.yaml in the scratch folder.
void write_centrifuge_case(const Scratch& scratch) {
  scratch.write("case.yaml", test_support::read_file(std::string(PARTIMIX_SOURCE_DIR) +
                                                     "/cases/cfdem_centrifuge.yaml"));
}

// A first step that fails by a RunError (a solve that does not converge: the momentum
// predictor given one iteration) was not caught by `check` and ended the program by
// std::terminate: it is bad input, exit 2, naming the first method's section and the reason.
// (The run error first met here, a grain's DEM step beyond its relaxation time in a fluid made a
// thousand times more viscous, is no longer an error: the DEM takes the drag backward in time.)
TEST(CheckCommand, AFirstStepThatFailsIsBadInputNotACrash) {
  const Scratch scratch;
  write_centrifuge_case(scratch);
  const Outcome outcome =
      run_partimix(scratch, {"check", "case.yaml", "--set", "cfd.max_iterations=1"});
  EXPECT_EQ(outcome.exit_code, 2) << outcome.err;
  EXPECT_THAT(outcome.err, HasSubstr("case.yaml:"));
  EXPECT_THAT(outcome.err, HasSubstr("cfd: the first step (dt = "));
  EXPECT_THAT(outcome.err, HasSubstr("did not converge"));
  EXPECT_THAT(scratch.work_entries(), ElementsAre("case.yaml"));
}

// The same case made a thousand times more viscous, with grains whose DEM step is then beyond
// their relaxation time, is good input: the drag is backward in time in the DEM's kicks.
TEST(CheckCommand, GrainsStepBeyondTheirRelaxationTimeInAViscousFluid) {
  const Scratch scratch;
  write_centrifuge_case(scratch);
  const Outcome outcome = run_partimix(
      scratch, {"check", "case.yaml", "--set", "fluid.viscosity=100", "--set", "time.dt=auto"});
  EXPECT_EQ(outcome.exit_code, 0) << outcome.err;
}

TEST(CommandLine, VersionPrintsTheVersion) {
  const Scratch scratch;
  const Outcome outcome = run_partimix(scratch, {"--version"});
  EXPECT_EQ(outcome.exit_code, 0) << outcome.err;
  EXPECT_EQ(outcome.out, std::string("partimix ") + PARTIMIX_VERSION + "\n");
}

TEST(CommandLine, HelpListsTheSubCommands) {
  const Scratch scratch;
  const Outcome outcome = run_partimix(scratch, {"--help"});
  EXPECT_EQ(outcome.exit_code, 0) << outcome.err;
  for (const char* command : {"run", "check", "plot"}) {
    EXPECT_THAT(outcome.out, HasSubstr(command));
  }
}

TEST(CommandLine, NoSubCommandIsBadInput) {
  const Scratch scratch;
  const Outcome outcome = run_partimix(scratch, {});
  EXPECT_EQ(outcome.exit_code, 2) << outcome.err;
  EXPECT_THAT(outcome.err, HasSubstr("subcommand"));
  EXPECT_TRUE(scratch.work_entries().empty());
}

}  // namespace
}  // namespace partimix::cli_test
