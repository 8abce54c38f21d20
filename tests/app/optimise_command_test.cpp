// `partimix optimise` (docs/design-loop.md) on 100 grains settled in a box, searching the grain
// radius in [3, 5] mm for the least mass in the box: the mass grows as r³, so the optimum is the
// lower bound, found within 1% of the range; the table, the evaluations and the plot are written;
// the same command with more evaluations resumes (the first runs are taken from the record, not
// run again); another search in the same folder and a bad bound are exit code 2.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "cli_support.hpp"
#include "grains_case.hpp"

namespace partimix::cli_test {
namespace {

using ::testing::HasSubstr;

const std::string kCase = kGrainsInABox + R"(analyses:
  - type: mass_in_region
    region: {min: [-0.06, -0.06, -0.01], max: [0.06, 0.06, 0.12]}
)";

std::vector<std::string> search(int evaluations) {
  return {"optimise",   "case.yaml",  "--vary",        "dem.fill.radius=0.003:0.005",
          "--minimise", "mass_final", "--evaluations", std::to_string(evaluations),
          "--out",      "search",     "--threads",     "1"};
}

nlohmann::json evaluations(const Scratch& scratch) {
  std::ifstream in(scratch.work() / "search" / "evaluations.json");
  return nlohmann::json::parse(in);
}

TEST(OptimiseCommand, FindsTheLowerBoundOfAMassGrowingWithTheRadius) {
  const Scratch scratch;
  scratch.write("case.yaml", kCase);
  const Outcome outcome = run_partimix(scratch, search(10));
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  EXPECT_THAT(outcome.err, HasSubstr("best: eval_"));
  const nlohmann::json record = evaluations(scratch);
  double best = 1.0;
  double best_value = 1e30;
  for (const nlohmann::json& item : record["evaluations"]) {
    if (item["value"].get<double>() < best_value) {
      best_value = item["value"].get<double>();
      best = item["x"][0].get<double>();
    }
  }
  EXPECT_NEAR(best, 0.003, 0.01 * 0.002);
  EXPECT_TRUE(std::filesystem::is_regular_file(scratch.work() / "search" / "optimise.csv"));
  EXPECT_TRUE(std::filesystem::is_regular_file(scratch.work() / "search" / "search.png"));
}

TEST(OptimiseCommand, MoreEvaluationsResumeFromTheRecord) {
  const Scratch scratch;
  scratch.write("case.yaml", kCase);
  ASSERT_EQ(run_partimix(scratch, search(3)).exit_code, 0);
  const auto first_time =
      std::filesystem::last_write_time(scratch.work() / "search" / "eval_000" / "run.json");
  const Outcome again = run_partimix(scratch, search(5));
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_THAT(again.err, HasSubstr("eval_002 (dem.fill.radius="));
  EXPECT_THAT(again.err, HasSubstr("(evaluated before)"));
  EXPECT_EQ(std::filesystem::last_write_time(scratch.work() / "search" / "eval_000" / "run.json"),
            first_time);
  EXPECT_EQ(evaluations(scratch)["evaluations"].size(), 5u);
}

TEST(OptimiseCommand, AnotherSearchInTheFolderAndABadBoundAreRefused) {
  const Scratch scratch;
  scratch.write("case.yaml", kCase);
  ASSERT_EQ(run_partimix(scratch, search(2)).exit_code, 0);
  std::vector<std::string> other = search(2);
  other[3] = "dem.fill.radius=0.003:0.0045";
  const Outcome refused = run_partimix(scratch, other);
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_THAT(refused.err, HasSubstr("holds another search"));
  std::vector<std::string> bad = search(2);
  bad[3] = "dem.fill.radius=0.005:0.003";
  bad[9] = "elsewhere";
  const Outcome bound = run_partimix(scratch, bad);
  EXPECT_EQ(bound.exit_code, 2);
  EXPECT_THAT(bound.err, HasSubstr("--vary"));
  EXPECT_FALSE(std::filesystem::exists(scratch.work() / "elsewhere"));
}

}  // namespace
}  // namespace partimix::cli_test
