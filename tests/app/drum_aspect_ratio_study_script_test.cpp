// tools/drum_aspect_ratio_study.py on hand-written run folders: the table sorted by the aspect
// ratio, the fitted rates copied from run.json, the energies per grain and the orientation order
// averaged over t >= --from (exact to the printed digits; NaN samples skipped, NaN for a run
// without the analyses), the plots, and bad input.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "support/temp_dir.hpp"
#include "tool_script.hpp"

namespace partimix::app {
namespace {

using test_support::read_file;
using test_support::TempDir;
using ::testing::HasSubstr;
using ::testing::StartsWith;

// A run of `grains` grains of aspect ratio sigma: kinetic energy 100, 100, 20, 40 J and
// rotational 0, 0, 10, 30 J at t = 0, 1, 2, 3 s, so over t >= 2 s the means per grain are
// 30 / grains and 20 / grains. With `oriented`, the two orientation analyses: flow alignment
// 0.9, NaN (no grain moving), 0.1, 0.3, nematic order 0.2, 0.2, 0.4, 0.6 and axial alignment
// -0.5, -0.5, -0.2, -0.4: over t >= 2 s 0.2, 0.5 and -0.3.
void write_run(const std::filesystem::path& folder, double sigma, int grains, double rate,
               bool oriented = false) {
  std::filesystem::create_directories(folder);
  std::ofstream(folder / "run.json")
      << R"({"case": {"dem": {"species": [{"shape": {"aspect_ratio": )" << sigma
      << R"(}}], "fill": {"count": )" << grains << R"(}}}, "figures": {"lacey_rate_exp": )" << rate
      << R"(, "lacey_rate_erf": )" << rate / 2 << "}}";
  std::ofstream csv(folder / "series.csv");
  if (oriented) {
    csv << "time [s],kinetic_energy [J],rotational_energy [J],lacey [-],flow.alignment [-],"
           "flow.nematic_order [-],axial.alignment [-]\n"
        << "0,100,0,0,0.9,0.2,-0.5\n1,100,0,0.3,nan,0.2,-0.5\n2,20,10,0.5,0.1,0.4,-0.2\n"
        << "3,40,30,0.7,0.3,0.6,-0.4\n";
    return;
  }
  csv << "time [s],kinetic_energy [J],rotational_energy [J],lacey [-]\n"
      << "0,100,0,0\n1,100,0,0.3\n2,20,10,0.5\n3,40,30,0.7\n";
}

TEST(DrumAspectRatioStudyScript, TabulatesRatesAndMeanEnergiesPerGrainByAspectRatio) {
  const TempDir dir;
  write_run(dir / "b", 2.0, 10, 0.3, true);
  write_run(dir / "a", 0.5, 5, 0.4);
  const ScriptOutcome outcome =
      run_tool_script(dir, "drum_aspect_ratio_study.py",
                      {(dir / "out").string(), (dir / "b").string(), (dir / "a").string()});
  ASSERT_EQ(outcome.exit_code, 0) << outcome.output;
  const std::string table = read_file(dir / "out" / "aspect_ratio_study.csv");
  EXPECT_THAT(table, HasSubstr("0.5,5,0.7,0.4,0.2,6.0,4.0,0.4,nan,nan,nan\n"
                               "2,10,0.7,0.3,0.15,3.0,2.0,0.4,0.2,0.5,-0.3"))
      << table;
  EXPECT_THAT(read_file(dir / "out" / "drum_aspect_ratio_lacey.png"), StartsWith("\x89PNG"));
  EXPECT_THAT(read_file(dir / "out" / "drum_aspect_ratio_rates.png"), StartsWith("\x89PNG"));
  EXPECT_THAT(read_file(dir / "out" / "drum_aspect_ratio_orientation.png"), StartsWith("\x89PNG"));
}

TEST(DrumAspectRatioStudyScript, AFolderWithoutARunIsBadInput) {
  const TempDir dir;
  write_run(dir / "a", 0.5, 5, 0.4);
  const ScriptOutcome outcome =
      run_tool_script(dir, "drum_aspect_ratio_study.py",
                      {(dir / "out").string(), (dir / "a").string(), (dir / "missing").string()});
  EXPECT_EQ(outcome.exit_code, 2);
  EXPECT_THAT(outcome.output, HasSubstr("run.json"));
}

}  // namespace
}  // namespace partimix::app
