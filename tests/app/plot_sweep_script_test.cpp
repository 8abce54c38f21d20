// tools/plot_sweep.py on a hand-written sweep.csv: the log-log fit of Np on Re, its plot, bad
// input, and the sweep's call of it.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <regex>
#include <string>
#include <vector>

#include "app/sweep_plot.hpp"
#include "support/temp_dir.hpp"
#include "tool_script.hpp"

namespace partimix::app {
namespace {

using test_support::read_file;
using test_support::TempDir;
using ::testing::HasSubstr;
using ::testing::StartsWith;

ScriptOutcome plot_sweep(const TempDir& dir, const std::vector<std::string>& options = {}) {
  std::vector<std::string> arguments{dir.path().string()};
  arguments.insert(arguments.end(), options.begin(), options.end());
  return run_tool_script(dir, "plot_sweep.py", arguments);
}

// Np = 40 / Re at four Reynolds numbers, plus a failed run without figures.
void write_laminar_sweep(const TempDir& dir) {
  std::ofstream csv(dir / "sweep.csv");
  csv << "run,fluid.viscosity,status,Np,Re\n";
  const double reynolds[] = {0.5, 1.0, 5.0, 10.0};
  for (int i = 0; i < 4; ++i)
    csv << "run_00" << i << ",1,"
        << "completed," << 40.0 / reynolds[i] << "," << reynolds[i] << "\n";
  csv << "run_004,2,failed,,\n";
}

TEST(PlotSweepScript, FitsSlopeMinusOneToNpOver40Re) {
  const TempDir dir;
  write_laminar_sweep(dir);
  const ScriptOutcome outcome = plot_sweep(dir);
  ASSERT_EQ(outcome.exit_code, 0) << outcome.output;
  std::smatch slope;
  ASSERT_TRUE(std::regex_search(outcome.output, slope, std::regex("slope = (\\S+)")))
      << outcome.output;
  EXPECT_NEAR(std::stod(slope[1].str()), -1.0, 1e-6);
  EXPECT_THAT(read_file(dir / "np_re.png"), StartsWith("\x89PNG"));
}

TEST(PlotSweepScript, FitsEachOfSeveralSweepsIntoOnePlot) {
  const TempDir newtonian("newtonian");
  write_laminar_sweep(newtonian);
  const TempDir shear_thinning("shear_thinning");
  {
    std::ofstream csv(shear_thinning / "sweep.csv");
    csv << std::setprecision(15) << "run,status,Np,Re\n";
    for (const double re : {2.0, 10.0})
      csv << "run,completed," << 50.0 * std::pow(re, -0.9) << "," << re << "\n";
  }
  const std::string png = (newtonian / "both.png").string();
  const ScriptOutcome outcome = plot_sweep(
      newtonian, {shear_thinning.path().string(), "--labels", "Newtonian", "CMC", "--out", png});
  ASSERT_EQ(outcome.exit_code, 0) << outcome.output;
  std::vector<double> slopes;
  const std::regex line("slope = (\\S+)");
  for (auto it = std::sregex_iterator(outcome.output.begin(), outcome.output.end(), line);
       it != std::sregex_iterator(); ++it)
    slopes.push_back(std::stod((*it)[1].str()));
  ASSERT_EQ(slopes.size(), 2U) << outcome.output;
  EXPECT_NEAR(slopes[0], -1.0, 1e-6);
  EXPECT_NEAR(slopes[1], -0.9, 1e-6);
  EXPECT_THAT(read_file(png), StartsWith("\x89PNG"));
  const ScriptOutcome labels = plot_sweep(newtonian, {"--labels", "a", "b"});
  EXPECT_EQ(labels.exit_code, 2);
  EXPECT_THAT(labels.output, HasSubstr("2 labels for 1 sweep folders"));
}

TEST(PlotSweepScript, IsWhatTheSweepRunsForTheNpRePlot) {
  const TempDir dir;
  write_laminar_sweep(dir);
  EXPECT_EQ(plot_np_re(dir.path()), 0);
  EXPECT_THAT(read_file(dir / "np_re.png"), StartsWith("\x89PNG"));
}

TEST(PlotSweepScript, MissingColumnOrFileIsBadInput) {
  const TempDir dir;
  const ScriptOutcome no_file = plot_sweep(dir);
  EXPECT_EQ(no_file.exit_code, 2);
  EXPECT_THAT(no_file.output, HasSubstr("sweep.csv does not exist"));
  write_laminar_sweep(dir);
  const ScriptOutcome no_column = plot_sweep(dir, {"--x", "Fr"});
  EXPECT_EQ(no_column.exit_code, 2);
  EXPECT_THAT(no_column.output, HasSubstr("no column 'Fr'"));
}

}  // namespace
}  // namespace partimix::app
