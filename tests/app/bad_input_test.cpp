// Bad input to `partimix run` exits with code 2, names where the problem is (file:line:column
// and key path, or --set) and writes nothing: not even the output folder.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "cli_support.hpp"
#include "grains_case.hpp"

namespace partimix::cli_test {
namespace {

using ::testing::ContainsRegex;
using ::testing::ElementsAre;
using ::testing::HasSubstr;

const std::string kTank2D = R"(name: tank_2d
solver: sph
dimensions: 2
gravity: [0, -9.81]
domain:
  min: [-0.1, -0.1]
  max: [0.7, 0.5]
time:
  end: 0.01
  output_interval: 0.005
sph:
  spacing: 0.02
fluid:
  density: 1000
  viscosity: 1.0e-3
  regions:
    - shape: box
      min: [0, 0]
      max: [0.2, 0.2]
walls:
  - shape: box
    min: [0, 0]
    max: [0.6, 0.4]
    open: [y+]
)";

const std::vector<std::string> kRun{"run", "case.yaml", "--out", "out", "-q", "-t", "1"};

std::string escaped(const std::string& text) {
  std::string regex;
  for (const char c : text) {
    if (std::string(".[]").find(c) != std::string::npos)
      regex += '\\';
    regex += c;
  }
  return regex;
}

// The start of the one-line error "error: case.yaml:LINE:COLUMN: KEY.PATH: message".
std::string location(int line, const std::string& key_path) {
  return "error: case\\.yaml:" + std::to_string(line) + ":[0-9]+: " + escaped(key_path) + ": ";
}

class BadInput : public ::testing::Test {
 protected:
  // Runs `arguments` on case.yaml holding `text`.
  Outcome run_case(const std::string& text, const std::vector<std::string>& arguments = kRun) {
    scratch_.write("case.yaml", text);
    return run_partimix(scratch_, arguments);
  }

  // Exit code 2 and nothing written beside the case file.
  void expect_rejected(const Outcome& outcome) const {
    EXPECT_EQ(outcome.exit_code, 2) << outcome.err;
    EXPECT_FALSE(fs::exists(scratch_.work() / "out"));
    EXPECT_THAT(scratch_.work_entries(), ElementsAre("case.yaml"));
  }

  Scratch scratch_;
};

TEST_F(BadInput, TheUnmodifiedCaseRuns) {
  const Outcome outcome = run_case(kTank2D);
  EXPECT_EQ(outcome.exit_code, 0) << outcome.err;
}

TEST_F(BadInput, MalformedYamlNamesTheParserPosition) {
  const Outcome outcome = run_case(replaced(kTank2D, "max: [0.7, 0.5]", "max: [0.7, 0.5"));
  expect_rejected(outcome);
  EXPECT_THAT(outcome.err, ContainsRegex("error: case\\.yaml:[0-9]+:[0-9]+: malformed YAML"));
}

TEST_F(BadInput, UnknownKeyIsNamed) {
  const std::string text = replaced(kTank2D, "  spacing: 0.02\n", "  spacing: 0.02\n  kernal: x\n");
  const Outcome outcome = run_case(text);
  expect_rejected(outcome);
  EXPECT_THAT(outcome.err, ContainsRegex(location(line_of(text, "kernal"), "sph.kernal")));
  EXPECT_THAT(outcome.err, HasSubstr("unknown key 'kernal'"));
}

TEST_F(BadInput, MisspeltRequiredKeyIsNamedAsUnknown) {
  const std::string text = replaced(kTank2D, "  spacing: 0.02", "  spacng: 0.02");
  const Outcome outcome = run_case(text);
  expect_rejected(outcome);
  EXPECT_THAT(outcome.err, ContainsRegex(location(line_of(text, "spacng"), "sph.spacng")));
  EXPECT_THAT(outcome.err, HasSubstr("unknown key 'spacng'"));
}

TEST_F(BadInput, WrongTypeIsNamed) {
  const std::string text = replaced(kTank2D, "  end: 0.01", "  end: abc");
  const Outcome outcome = run_case(text);
  expect_rejected(outcome);
  EXPECT_THAT(outcome.err, ContainsRegex(location(line_of(text, "end: abc"), "time.end")));
  EXPECT_THAT(outcome.err, HasSubstr("expected a number, got 'abc'"));
}

TEST_F(BadInput, MissingRequiredKeyPointsAtItsMap) {
  const std::string text = replaced(kTank2D, "  density: 1000\n", "");
  const Outcome outcome = run_case(text);
  expect_rejected(outcome);
  EXPECT_THAT(outcome.err, ContainsRegex(location(line_of(text, "viscosity"), "fluid.density")));
  EXPECT_THAT(outcome.err, HasSubstr("missing required key 'density'"));
}

TEST_F(BadInput, OutOfRangeValueIsNamed) {
  const std::string text = replaced(kTank2D, "  spacing: 0.02", "  spacing: -1");
  const Outcome outcome = run_case(text);
  expect_rejected(outcome);
  EXPECT_THAT(outcome.err, ContainsRegex(location(line_of(text, "spacing"), "sph.spacing")));
  EXPECT_THAT(outcome.err, HasSubstr("must be > 0, got -1"));
}

TEST_F(BadInput, BadSetValueNamesSet) {
  std::vector<std::string> arguments = kRun;
  arguments.insert(arguments.end(), {"--set", "sph.kernel=foo"});
  const Outcome outcome = run_case(kTank2D, arguments);
  expect_rejected(outcome);
  EXPECT_THAT(outcome.err, HasSubstr("error: --set: sph.kernel: unknown value 'foo'"));
}

TEST_F(BadInput, CaseThatPlacesParticlesOutsideTheDomainIsNamed) {
  const std::string text = replaced(kTank2D, "min: [-0.1, -0.1]", "min: [0.1, 0.1]");
  const Outcome outcome = run_case(text);
  expect_rejected(outcome);
  EXPECT_THAT(outcome.err, ContainsRegex(location(line_of(text, "min: [0.1, 0.1]"), "domain")));
  EXPECT_THAT(outcome.err, HasSubstr("lies outside the domain"));
}

TEST_F(BadInput, MissingCaseFileIsNamed) {
  const Outcome outcome = run_partimix(scratch_, {"run", "missing.yaml", "--out", "out", "-q"});
  EXPECT_EQ(outcome.exit_code, 2) << outcome.err;
  EXPECT_THAT(outcome.err, HasSubstr("error: missing.yaml: cannot read"));
  EXPECT_TRUE(scratch_.work_entries().empty());
}

TEST_F(BadInput, UnknownOptionIsRejected) {
  std::vector<std::string> arguments = kRun;
  arguments.push_back("--bogus");
  const Outcome outcome = run_case(kTank2D, arguments);
  expect_rejected(outcome);
  EXPECT_THAT(outcome.err, HasSubstr("--bogus"));
}

// The location of the item `index` of the list `list`, each item one line long.
std::string item_location(const std::string& text, const std::string& list, int index) {
  return location(line_of(text, list + ":") + 1 + index, list + "[" + std::to_string(index) + "]");
}

// Sizes that would cost without bound are refused at once, at the key that drives them, before
// anything is allocated or written (issue 15: a 4294967296 m wall ran out of memory).
TEST_F(BadInput, AWallTooLargeToSampleIsRefusedBeforeItAllocates) {
  std::string text = replaced(kTank2D, "max: [0.6, 0.4]", "max: [4294967296, 0.4]");
  text = replaced(text, "max: [0.7, 0.5]", "max: [4294967297, 0.5]");
  const Outcome outcome = run_case(text);
  expect_rejected(outcome);
  EXPECT_THAT(outcome.err, ContainsRegex(item_location(text, "walls", 0)));
  EXPECT_THAT(outcome.err, HasSubstr("more than limits.lattice_points = 1e+09"));
}

TEST_F(BadInput, AFluidRegionOfAstronomicalHeightIsRefused) {
  std::string text = replaced(kTank2D, "max: [0.2, 0.2]", "max: [0.2, 1.0e19]");
  text = replaced(text, "max: [0.7, 0.5]", "max: [0.7, 2.0e19]");
  const Outcome outcome = run_case(text);
  expect_rejected(outcome);
  EXPECT_THAT(outcome.err,
              ContainsRegex(location(line_of(text, "- shape: box"), "fluid.regions[0]")));
}

TEST_F(BadInput, MoreParticlesThanTheLimitAreRefusedAndTheLimitCanBeRaised) {
  std::vector<std::string> arguments = kRun;
  arguments.insert(arguments.end(), {"--set", "limits.particles=50"});
  const Outcome outcome = run_case(kTank2D, arguments);
  expect_rejected(outcome);
  EXPECT_THAT(outcome.err, HasSubstr("more than limits.particles = 50"));
  arguments.back() = "limits.particles=1e6";
  EXPECT_EQ(run_case(kTank2D, arguments).exit_code, 0);
}

TEST_F(BadInput, AGrainCountPastTheLimitIsRefusedAtOnce) {
  const std::string text = replaced(kGrainsInABox, "count: 100", "count: 100000000");
  const Outcome outcome = run_case(text);
  expect_rejected(outcome);
  EXPECT_THAT(outcome.err, ContainsRegex(location(line_of(text, "count:"), "dem.fill.count")));
  EXPECT_THAT(outcome.err, HasSubstr("more than limits.particles"));
}

TEST_F(BadInput, GrainsThatCannotFitAreRefusedWithoutDrawingCandidates) {
  const std::string text = replaced(kGrainsInABox, "count: 100", "count: 2000000");
  const Outcome outcome = run_case(text);
  expect_rejected(outcome);
  EXPECT_THAT(outcome.err, HasSubstr("dem.fill: "));
  EXPECT_THAT(outcome.err, HasSubstr("at the densest packing"));
}

TEST_F(BadInput, MoreFillAttemptsThanTheBoundAreRefused) {
  const std::string text =
      replaced(kGrainsInABox, "count: 100", "count: 100\n    attempts: 2000000");
  const Outcome outcome = run_case(text);
  expect_rejected(outcome);
  EXPECT_THAT(outcome.err,
              ContainsRegex(location(line_of(text, "attempts:"), "dem.fill.attempts")));
  EXPECT_THAT(outcome.err, HasSubstr("more than 1e+06 failed candidates"));
}

TEST_F(BadInput, ATinySampleIntervalIsRefusedNotLoopedOn) {
  std::vector<std::string> arguments = kRun;
  arguments.insert(arguments.end(), {"--set", "time.sample_interval=1e-20"});
  const Outcome outcome = run_case(kTank2D, arguments);
  expect_rejected(outcome);
  EXPECT_THAT(outcome.err, HasSubstr("error: --set: time.sample_interval: "));
  EXPECT_THAT(outcome.err, HasSubstr("more than limits.series_rows"));
}

TEST_F(BadInput, ATinyFixedTimeStepIsRefused) {
  std::vector<std::string> arguments = kRun;
  arguments.insert(arguments.end(), {"--set", "time.dt=1e-22"});
  const Outcome outcome = run_case(kTank2D, arguments);
  expect_rejected(outcome);
  EXPECT_THAT(outcome.err, HasSubstr("error: --set: time.dt: "));
}

TEST_F(BadInput, AFixedTimeStepAboveTheStableOneFailsCheck) {
  const Outcome outcome = run_case(kTank2D, {"check", "case.yaml", "--set", "time.dt=0.001"});
  EXPECT_EQ(outcome.exit_code, 2) << outcome.err;
  EXPECT_THAT(outcome.err, HasSubstr("error: --set: time.dt: time.dt = 0.001 s exceeds"));
}

TEST_F(BadInput, TwoAnalysesWritingTheSameColumnsAreRefusedUnlessNamed) {
  const std::string analyses = R"(analyses:
  - {type: front_position, axis: x}
  - {type: front_position, axis: x}
)";
  const std::string text = kTank2D + analyses;
  for (const auto& arguments : {std::vector<std::string>{"check", "case.yaml"}, kRun}) {
    const Outcome outcome = run_case(text, arguments);
    expect_rejected(outcome);
    EXPECT_THAT(outcome.err, ContainsRegex(item_location(text, "analyses", 1)));
    EXPECT_THAT(outcome.err, HasSubstr("already written by analyses[0]"));
  }
  const std::string named = kTank2D + R"(analyses:
  - {type: front_position, axis: x, name: front}
  - {type: front_position, axis: x, name: front_again}
)";
  EXPECT_EQ(run_case(named).exit_code, 0);
  EXPECT_THAT(read_series(scratch_.work() / "out" / "series.csv").header,
              HasSubstr("front.front_x [m],front_again.front_x [m]"));
}

TEST_F(BadInput, APeriodicAxisTooShortIsALocatedErrorNamingTheMinimum) {
  std::string sph = replaced(kTank2D, "max: [0.7, 0.5]", "max: [0.0, 0.5]\n  periodic: [x]");
  sph = replaced(sph, "min: [-0.1, -0.1]", "min: [-0.05, -0.1]");
  sph = replaced(sph, "max: [0.2, 0.2]", "max: [-0.01, 0.2]");
  sph = replaced(sph, "min: [0, 0]", "min: [-0.04, 0]");
  sph = replaced(
      sph, "walls:\n  - shape: box\n    min: [0, 0]\n    max: [0.6, 0.4]\n    open: [y+]\n", "");
  const Outcome outcome = run_case(sph);
  expect_rejected(outcome);
  EXPECT_THAT(outcome.err, ContainsRegex(location(line_of(sph, "periodic:"), "domain.periodic")));
  EXPECT_THAT(outcome.err, HasSubstr("the periodic axis x is 0.05 m long; it must be at least"));
  std::string dem = replaced(kGrainsInABox, "max: [0.06, 0.06, 0.12]",
                             "max: [0.06, 0.06, 0.12]\n  periodic: [x]");
  dem = replaced(dem, "min: [-0.06, -0.06, -0.01]", "min: [0.04, -0.06, -0.01]");
  dem = replaced(dem, "min: [-0.04, -0.04, 0.0]", "min: [0.045, -0.04, 0.0]");
  dem = replaced(dem, "max: [0.04, 0.04, 0.08]", "max: [0.055, 0.04, 0.08]");
  dem = replaced(dem, "count: 100", "count: 10");
  const Outcome grains = run_case(dem);
  expect_rejected(grains);
  EXPECT_THAT(grains.err, ContainsRegex(location(line_of(dem, "periodic:"), "domain.periodic")));
  // The interaction radius of grains of 4 mm: 2 R + the pair list's skin of 0.5 R.
  EXPECT_THAT(grains.err, HasSubstr("3 x 0.01 m = 0.03 m"));
}

TEST_F(BadInput, ZeroThreadsIsRefusedInPlainWords) {
  std::vector<std::string> arguments = kRun;
  arguments.back() = "0";
  const Outcome outcome = run_case(kTank2D, arguments);
  expect_rejected(outcome);
  EXPECT_THAT(outcome.err, HasSubstr("--threads"));
  EXPECT_LT(outcome.err.size(), 200u) << outcome.err;
}

TEST_F(BadInput, CheckShowsTheSettlingOfGrainsAndItsEstimate) {
  const Outcome outcome = run_case(kGrainsInABox, {"check", "case.yaml"});
  EXPECT_EQ(outcome.exit_code, 0) << outcome.err;
  EXPECT_THAT(outcome.err, HasSubstr("dem: settling the grains (up to t = 0.05 s)"));
  EXPECT_THAT(outcome.err, HasSubstr("steps (estimate)"));
  EXPECT_THAT(scratch_.work_entries(), ElementsAre("case.yaml"));
}

}  // namespace
}  // namespace partimix::cli_test
