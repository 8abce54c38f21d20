// Bad input to `partimix run` exits with code 2, names where the problem is (file:line:column
// and key path, or --set) and writes nothing: not even the output folder.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "cli_support.hpp"

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
  const Outcome outcome = run_case(replaced(kTank2D, "min: [-0.1, -0.1]", "min: [0.1, 0.1]"));
  expect_rejected(outcome);
  EXPECT_THAT(outcome.err, HasSubstr("error: case.yaml: domain: "));
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

}  // namespace
}  // namespace partimix::cli_test
