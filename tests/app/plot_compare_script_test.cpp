// tools/plot_compare.py on hand-written runs: one column of several series.csv files in one
// PNG, and bad input (a missing column, labels that do not match the runs).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "support/temp_dir.hpp"
#include "tool_script.hpp"

namespace partimix::app {
namespace {

using test_support::read_file;
using test_support::TempDir;
using ::testing::HasSubstr;
using ::testing::StartsWith;

ScriptOutcome plot_compare(const TempDir& dir, const std::vector<std::string>& arguments) {
  return run_tool_script(dir, "plot_compare.py", arguments);
}

// A run folder dir/name whose xi falls from 1 as exp(-rate t).
std::string write_run(const TempDir& dir, const std::string& name, double rate) {
  const std::filesystem::path run = dir / name;
  std::filesystem::create_directories(run);
  std::ofstream csv(run / "series.csv");
  csv << "time [s],xi [-]\n";
  for (int k = 0; k <= 10; ++k)
    csv << 0.1 * k << "," << std::exp(-rate * 0.1 * k) << "\n";
  return run.string();
}

TEST(PlotCompareScript, DrawsOneColumnOfSeveralRunsIntoOnePng) {
  const TempDir dir;
  const std::string png = (dir / "xi.png").string();
  const ScriptOutcome outcome =
      plot_compare(dir, {write_run(dir, "central", 1.0), write_run(dir, "planetary", 3.0), "--y",
                         "xi", "--out", png, "--labels", "central", "planetary"});
  ASSERT_EQ(outcome.exit_code, 0) << outcome.output;
  EXPECT_THAT(outcome.output, HasSubstr("2 runs"));
  EXPECT_THAT(read_file(png), StartsWith("\x89PNG"));
}

TEST(PlotCompareScript, MissingColumnOrWrongLabelCountIsBadInput) {
  const TempDir dir;
  const std::string run = write_run(dir, "central", 1.0);
  const std::string png = (dir / "out.png").string();
  const ScriptOutcome no_column = plot_compare(dir, {run, "--y", "lacey", "--out", png});
  EXPECT_EQ(no_column.exit_code, 2);
  EXPECT_THAT(no_column.output, HasSubstr("no column 'lacey'"));
  const ScriptOutcome labels =
      plot_compare(dir, {run, "--y", "xi", "--out", png, "--labels", "a", "b"});
  EXPECT_EQ(labels.exit_code, 2);
  EXPECT_THAT(labels.output, HasSubstr("2 labels for 1 runs"));
  EXPECT_FALSE(std::filesystem::exists(png));
}

}  // namespace
}  // namespace partimix::app
