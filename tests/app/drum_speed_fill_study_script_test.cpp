// tools/drum_speed_fill_study.py on hand-written run folders: one row per run sorted by aspect
// ratio, speed and falling fill, the drum's diameter and the fill (the grains' volume over the
// drum's) from the case, the rates and energies as the aspect-ratio study gives them, the plot,
// and bad input.
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

// Three grains of radius 10 mm (spheres, or spheroids of that equivalent radius) in a drum of
// radius `radius` 40 mm long: a fill of 1% at 100 mm and 0.25% at 200 mm. Kinetic energy 100,
// 100, 20, 40 J and rotational 0, 0, 10, 30 J at t = 0, 1, 2, 3 s: over t >= 2 s the means per
// grain are 10 and 20 / 3 J.
void write_run(const std::filesystem::path& folder, const std::string& species, double radius,
               double rpm, double rate) {
  std::filesystem::create_directories(folder);
  std::ofstream(folder / "run.json")
      << R"({"case": {"domain": {"min": [-1, -1, 0.01], "max": [1, 1, 0.05]}, "walls": [{"radius": )"
      << radius << R"(, "motion": {"rpm": )" << rpm << R"(}}], "dem": {"species": [)" << species
      << R"(], "fill": {"count": 3, "radius": 0.01}}}, "figures": {"lacey_rate_exp": )" << rate
      << R"(, "lacey_rate_erf": )" << rate / 2 << "}}";
  std::ofstream csv(folder / "series.csv");
  csv << "time [s],kinetic_energy [J],rotational_energy [J],lacey [-]\n"
      << "0,100,0,0\n1,100,0,0.3\n2,20,10,0.5\n3,40,30,0.7\n";
}

const std::string kSphere = R"({"name": "a"})";
const std::string kSpheroid = R"({"shape": {"aspect_ratio": 1.5, "equivalent_radius": 0.01}})";

TEST(DrumSpeedFillStudyScript, TabulatesEachRunWithItsDrumSpeedAndFill) {
  const TempDir dir;
  write_run(dir / "a", kSpheroid, 0.1, 30, 0.4);
  write_run(dir / "b", kSphere, 0.2, 30, 0.2);
  write_run(dir / "c", kSphere, 0.1, 30, 0.3);
  write_run(dir / "d", kSphere, 0.1, 20, 0.1);
  const ScriptOutcome outcome =
      run_tool_script(dir, "drum_speed_fill_study.py",
                      {(dir / "out").string(), (dir / "a").string(), (dir / "b").string(),
                       (dir / "c").string(), (dir / "d").string(), "--from", "2"});
  ASSERT_EQ(outcome.exit_code, 0) << outcome.output;
  const std::string table = read_file(dir / "out" / "speed_fill_study.csv");
  EXPECT_THAT(table, HasSubstr("1.0,20,200.0,1.0"));
  EXPECT_THAT(table, HasSubstr("\n1.0,30,200.0,1.0"));
  EXPECT_THAT(table, HasSubstr("\n1.0,30,400.0,0.25"));
  EXPECT_THAT(table, HasSubstr("\n1.5,30,200.0,1.0"));
  EXPECT_LT(table.find("1.0,20,"), table.find("1.0,30,200"));
  EXPECT_LT(table.find("1.0,30,200"), table.find("1.0,30,400"));
  EXPECT_LT(table.find("1.0,30,400"), table.find("1.5,30,200"));
  EXPECT_THAT(table, HasSubstr(",0.7,0.4,0.2,10.0,6.66"));
  EXPECT_THAT(read_file(dir / "out" / "drum_speed_fill_rates.png"), StartsWith("\x89PNG"));
}

TEST(DrumSpeedFillStudyScript, ARunWithoutItsDrumIsBadInput) {
  const TempDir dir;
  write_run(dir / "a", kSphere, 0.1, 30, 0.4);
  std::ofstream(dir / "a" / "run.json")
      << R"({"case": {"dem": {"species": [{}], "fill": {"count": 3}}}, "figures": {}})";
  const ScriptOutcome outcome = run_tool_script(dir, "drum_speed_fill_study.py",
                                                {(dir / "out").string(), (dir / "a").string()});
  EXPECT_EQ(outcome.exit_code, 2);
  EXPECT_THAT(outcome.output, HasSubstr("drum_speed_fill_study"));
}

}  // namespace
}  // namespace partimix::app
