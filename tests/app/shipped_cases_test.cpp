// Every case file in cases/ loads, builds and runs its first steps to completion at its own
// resolution, with its analyses: a case that a change of keys or defaults breaks fails here
// rather than in a user's hands. The physics of the cases is checked in tests/validation/. DEM
// cases settle their grains for 0.01 s only (settling 10,000 grains takes minutes), which skips
// nothing but the settling's length.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "dem/dem_section.hpp"
#include "io/case.hpp"
#include "support/case_run.hpp"

namespace partimix {
namespace {

std::vector<std::string> shipped_cases() {
  std::vector<std::string> files;
  const std::filesystem::path folder = std::filesystem::path(PARTIMIX_SOURCE_DIR) / "cases";
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    if (entry.path().extension() == ".yaml")
      files.push_back(entry.path().string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

// A few steps: 0.002 s, or a tenth of the case's first frame where that comes sooner, but never
// less than one sample (the gel droplet, whose gas bounds its step to 7.5 ns, writes a frame
// every 10 us and samples every 1 us: 1 us, 133 steps); a DEM fill settles for a short
// time only (grains placed by the case do not settle). Under the sanitizers, where a step of
// the 171k-particle dam break takes seconds (its 0.002 s took 287 s), one step and a settling of
// a step or two: what they look for is in the code each step runs, not in the step count.
std::vector<std::string> first_steps(const io::Case& the_case) {
  const double span =
      std::min({0.002, the_case.time.output_interval,
                std::max(the_case.time.sample_interval, 0.1 * the_case.time.output_interval)});
  const std::string end = PARTIMIX_SANITIZED ? "time.end=1e-6" : fmt::format("time.end={}", span);
  if (the_case.method("dem") == nullptr || !the_case.section<dem::DemSection>("dem").fill)
    return {end};
  return {end, PARTIMIX_SANITIZED ? "dem.fill.settle_time=1e-4" : "dem.fill.settle_time=0.01"};
}

// One test per case file, so that ctest runs them side by side.
class ShippedCases : public ::testing::TestWithParam<std::string> {};

TEST_P(ShippedCases, RunsItsFirstSteps) {
  const std::string& file = GetParam();
  const io::Case the_case = io::load_case(file, first_steps(io::load_case(file)));
  const test_support::CaseRun run = test_support::run_case(the_case);
  EXPECT_EQ(run.summary.status, "completed");
  EXPECT_GT(run.summary.steps, 0U);
  for (const auto& [name, value] : run.figures)
    EXPECT_TRUE(std::isfinite(value)) << name;
}

// The test is named after the case file's stem (letters, digits and underscores in cases/).
std::string case_name(const ::testing::TestParamInfo<std::string>& info) {
  return std::filesystem::path(info.param).stem().string();
}

INSTANTIATE_TEST_SUITE_P(EveryCaseFile, ShippedCases, ::testing::ValuesIn(shipped_cases()),
                         case_name);

TEST(ShippedCasesFolder, HoldsTheCases) {
  EXPECT_GE(shipped_cases().size(), 10U);
}

}  // namespace
}  // namespace partimix
