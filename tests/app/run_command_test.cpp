// `partimix run` end to end on a small 3D dam break: series.csv, the frames and their .pvd
// collection, run.json, and --set.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include "cli_support.hpp"
#include "dam_break_case.hpp"

namespace partimix::cli_test {
namespace {

using ::testing::ElementsAreArray;
using ::testing::HasSubstr;
using ::testing::StartsWith;

// The frames a run writes (src/app/runner.cpp): one at t = 0, one at the first step at or past
// each later multiple of output_interval, and one at the end unless the end is such a multiple
// (while a step is shorter than output_interval).
std::size_t expected_frames(double end, double output_interval) {
  const double tolerance = 1e-9 * end;
  const double multiples = std::floor((end + tolerance) / output_interval);
  const bool end_is_output_time = std::abs(end - multiples * output_interval) <= tolerance;
  return 1 + static_cast<std::size_t>(multiples) + (end_is_output_time ? 0 : 1);
}

class RunCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    scratch_.write("case.yaml", kDamBreak3D);
    outcome_ = run_partimix(scratch_, {"run", "case.yaml", "--out", "out", "-q", "-t", "1"});
    ASSERT_EQ(outcome_.exit_code, 0) << outcome_.err;
  }

  fs::path out() const { return scratch_.work() / "out"; }

  Scratch scratch_;
  Outcome outcome_;
};

TEST_F(RunCommand, SeriesHasNamedColumnsWithUnitsUpToTheEndTime) {
  const Series series = read_series(out() / "series.csv");
  EXPECT_EQ(series.header,
            "time [s],step [-],dt [s],kinetic_energy [J],max_speed [m/s],front_x [m]");
  ASSERT_GE(series.rows.size(), 5u);
  for (std::size_t i = 0; i < series.rows.size(); ++i) {
    ASSERT_EQ(series.rows[i].size(), 6u) << "row " << i;
    if (i > 0) {
      EXPECT_GT(series.rows[i][0], series.rows[i - 1][0]) << "row " << i;
    }
  }
  EXPECT_EQ(series.rows.front()[0], 0.0);
  EXPECT_NEAR(series.rows.back()[0], kDamBreakEnd, 1e-9);
}

TEST_F(RunCommand, CollectionListsOneFramePerOutputTimeAndOneAtTheEnd) {
  const std::vector<FrameEntry> frames = read_pvd(out() / "sph.pvd");
  ASSERT_EQ(frames.size(), expected_frames(kDamBreakEnd, kDamBreakOutputInterval));
  EXPECT_EQ(frames.front().time, 0.0);
  EXPECT_NEAR(frames.back().time, kDamBreakEnd, 1e-9);
  for (std::size_t i = 1; i < frames.size(); ++i) {
    EXPECT_GT(frames[i].time, frames[i - 1].time) << frames[i].file;
  }
  EXPECT_THAT(frame_files(out()), ElementsAreArray(files_of(frames)));
}

TEST_F(RunCommand, FramesHoldEveryParticleAndTheOutputFields) {
  const nlohmann::json run = read_json(out() / "run.json").at("run");
  const std::string points = "NumberOfPoints=\"" + run.at("particles").dump() + "\"";
  for (const auto& frame : read_pvd(out() / "sph.pvd")) {
    const std::string text = read_file(out() / frame.file);
    EXPECT_THAT(text, StartsWith("<?xml")) << frame.file;
    EXPECT_THAT(text, HasSubstr(points)) << frame.file;
    for (const char* field : {"velocity", "density", "pressure", "id", "kind"}) {
      EXPECT_THAT(text, HasSubstr("Name=\"" + std::string(field) + "\"")) << frame.file;
    }
  }
}

TEST_F(RunCommand, RunJsonRecordsTheResolvedCaseAndTheRun) {
  const nlohmann::json json = read_json(out() / "run.json");
  EXPECT_EQ(json.at("partimix_version"), PARTIMIX_VERSION);
  EXPECT_EQ(json.at("case_file"), "case.yaml");
  EXPECT_EQ(json.at("case").at("sph").at("spacing"), kDamBreakSpacing);
  EXPECT_EQ(json.at("case").at("sph").at("smoothing_ratio"), 1.5);
  EXPECT_TRUE(json.at("derived").is_object());
  const nlohmann::json& run = json.at("run");
  EXPECT_EQ(run.at("status"), "completed");
  EXPECT_EQ(run.at("message"), "");
  EXPECT_GT(run.at("particles").get<long>(), 0);
  EXPECT_GT(run.at("steps").get<long>(), 0);
  EXPECT_NEAR(run.at("simulated_time").get<double>(), kDamBreakEnd, 1e-9);
  EXPECT_GT(run.at("wall_seconds").get<double>(), 0.0);
  EXPECT_EQ(run.at("threads"), 1);
  EXPECT_GT(run.at("particle_steps_per_second").get<double>(), 0.0);
}

TEST_F(RunCommand, SetOverridesTheEndTime) {
  const Outcome shorter = run_partimix(
      scratch_, {"run", "case.yaml", "--out", "short", "-q", "-t", "1", "--set", "time.end=0.03"});
  ASSERT_EQ(shorter.exit_code, 0) << shorter.err;
  const nlohmann::json json = read_json(scratch_.work() / "short" / "run.json");
  EXPECT_EQ(json.at("case").at("time").at("end"), 0.03);
  EXPECT_NEAR(json.at("run").at("simulated_time").get<double>(), 0.03, 1e-9);
  EXPECT_NEAR(read_series(scratch_.work() / "short" / "series.csv").rows.back()[0], 0.03, 1e-9);
}

// `partimix plot` on the output folder of the run.
class PlotCommand : public RunCommand {};

TEST_F(PlotCommand, WritesTheOverviewPng) {
  const Outcome plot = run_partimix(scratch_, {"plot", "out"});
  ASSERT_EQ(plot.exit_code, 0) << plot.out << plot.err;
  const fs::path overview = out() / "plots" / "overview.png";
  ASSERT_TRUE(fs::exists(overview));
  EXPECT_THAT(read_file(overview), StartsWith("\x89PNG"));
}

// The folder's name reaches the plot script as one argument: no shell ever reads it.
TEST_F(PlotCommand, AFolderNameWithShellSyntaxIsOnlyAName) {
  const std::string name = "q'; touch INJECTED; echo '$(touch INJECTED2)";
  fs::rename(out(), scratch_.work() / name);
  const Outcome plot = run_partimix(scratch_, {"plot", name});
  EXPECT_EQ(plot.exit_code, 0) << plot.out << plot.err;
  EXPECT_TRUE(fs::exists(scratch_.work() / name / "plots" / "overview.png"));
  EXPECT_FALSE(fs::exists(scratch_.work() / "INJECTED"));
  EXPECT_FALSE(fs::exists(scratch_.work() / "INJECTED2"));
  const Outcome missing = run_partimix(scratch_, {"plot", "q'; touch INJECTED; '"});
  EXPECT_NE(missing.exit_code, 0);
  EXPECT_FALSE(fs::exists(scratch_.work() / "INJECTED"));
}

}  // namespace
}  // namespace partimix::cli_test
