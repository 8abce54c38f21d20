// The results table of a sweep: a run folder's run.json read into a record (status and
// "figures"), the union of the figures as columns, sweep.csv, and when the Np-Re plot applies.
#include "app/sweep_table.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "app/run_record.hpp"
#include "app/sweep_plot.hpp"
#include "support/temp_dir.hpp"

namespace partimix::app {
namespace {

using test_support::read_file;
using test_support::TempDir;
using ::testing::ElementsAre;
using ::testing::Pair;

RunRecord record_of(const TempDir& dir, const std::string& run_json) {
  std::ofstream(dir / "run.json") << run_json;
  return read_run_record(dir.path());
}

TEST(RunRecord, ReadsTheStatusAndTheNumericFigures) {
  const TempDir dir;
  const RunRecord record = record_of(dir, R"({"run": {"status": "completed", "steps": 3},
      "figures": {"Re": 1.0, "Np": 12.3, "xi_final": 0.004, "note": "text", "nan": null},
      "caveats": {"Np": "a short window", "Re": 3}, "figure_units": {"Np": "-", "xi_final": 1}})");
  EXPECT_EQ(record.status, "completed");
  EXPECT_THAT(record.figures,
              ElementsAre(Pair("Np", 12.3), Pair("Re", 1.0), Pair("xi_final", 0.004)));
  EXPECT_THAT(record.caveats, ElementsAre(Pair("Np", "a short window")));
  EXPECT_THAT(record.units, ElementsAre(Pair("Np", "-")));
}

TEST(RunRecord, WithoutFiguresHasNone) {
  const TempDir dir;
  const RunRecord record = record_of(dir, R"({"run": {"status": "failed"}})");
  EXPECT_EQ(record.status, "failed");
  EXPECT_TRUE(record.figures.empty());
}

TEST(RunRecord, IsFailedWithoutAFinishedRunJson) {
  const TempDir dir;
  EXPECT_EQ(read_run_record(dir.path()).status, "failed");
  EXPECT_EQ(record_of(dir, "{\"run\": {\"stat").status, "failed");
  EXPECT_EQ(record_of(dir, R"({"run": {"status": "running"}})").status, "failed");
}

SweepTable two_runs() {
  return {{"fluid.viscosity", "gravity"},
          {{"run_000",
            {"1e-3", "[0,-9.81]"},
            {"completed", {{"Np", 40.0}, {"Re", 1.0}}, {{"Np", "a short window"}}, {{"Np", ""}}}},
           {"run_001", {"2e-3", "[0,-4.9]"}, {"failed", {{"xi_final", 0.25}}, {}, {}}}}};
}

TEST(SweepTable, CsvHasTheKeysTheStatusTheUnionOfTheFiguresAndTheUnreliableOnes) {
  const TempDir dir;
  write_sweep_csv(dir / "sweep.csv", two_runs());
  EXPECT_EQ(read_file(dir / "sweep.csv"),
            "run,fluid.viscosity,gravity,status,Np [-],Re [-],xi_final [-],unreliable\n"
            "run_000,1e-3,\"[0,-9.81]\",completed,40,1,,Np\n"
            "run_001,2e-3,\"[0,-4.9]\",failed,,,0.25,\n");
  EXPECT_FALSE(std::filesystem::exists(dir / "sweep.csv.tmp"));
}

TEST(SweepTable, NpRePlotNeedsTwoRowsWithPositiveReAndNp) {
  SweepTable table = two_runs();
  EXPECT_FALSE(can_plot_np_re(table));
  table.rows[1].record.figures = {{"Np", 4.0}, {"Re", 10.0}};
  EXPECT_TRUE(can_plot_np_re(table));
  table.rows[1].record.figures["Re"] = 0.0;
  EXPECT_FALSE(can_plot_np_re(table));
}

}  // namespace
}  // namespace partimix::app
