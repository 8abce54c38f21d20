// run.json: the composed document reads back equal; the summary carries the throughput.
#include "io/run_metadata.hpp"

#include <gtest/gtest.h>

#include <string>

#include "core/error.hpp"
#include "io/test_files.hpp"

namespace partimix::io {
namespace {

using test::read_file;
using test::TempDir;

// A resumed run: 500 steps in all, the last 200 in 0.5 s of this process.
RunSummary example_summary() {
  return {"completed", "", 1000, 500, 0.25, 2.0, 4, 200, 0.5};
}

TEST(RunMetadata, SummaryHasEveryMemberAndThroughput) {
  const nlohmann::json json = to_json(example_summary());
  EXPECT_EQ(json.at("status"), "completed");
  EXPECT_EQ(json.at("message"), "");
  EXPECT_EQ(json.at("particles"), 1000);
  EXPECT_EQ(json.at("steps"), 500);
  EXPECT_EQ(json.at("simulated_time"), 0.25);
  EXPECT_EQ(json.at("wall_seconds"), 2.0);
  EXPECT_EQ(json.at("threads"), 4);
  EXPECT_EQ(json.at("particle_steps_per_second"), 250000.0);
  EXPECT_EQ(json.at("process_steps"), 200);
  EXPECT_EQ(json.at("process_wall_seconds"), 0.5);
  EXPECT_EQ(json.at("process_particle_steps_per_second"), 400000.0);
}

TEST(RunMetadata, ZeroWallTimeGivesZeroThroughput) {
  RunSummary summary = example_summary();
  summary.wall_seconds = 0.0;
  summary.process_wall_seconds = 0.0;
  EXPECT_EQ(to_json(summary).at("particle_steps_per_second"), 0.0);
  EXPECT_EQ(to_json(summary).at("process_particle_steps_per_second"), 0.0);
}

TEST(RunMetadata, WrittenDocumentRoundTrips) {
  TempDir dir;
  const nlohmann::json content = {{"version", "0.1.0"},
                                  {"case", {{"time", {{"end", 1.0}}}, {"name", "tank"}}},
                                  {"run", to_json(example_summary())}};
  write_run_json(dir / "run.json", content);
  const std::string text = read_file(dir / "run.json");
  EXPECT_EQ(nlohmann::json::parse(text), content);
  EXPECT_NE(text.find("\n  \"run\": {"), std::string::npos) << "not indented";
  EXPECT_EQ(text.back(), '\n');
  EXPECT_EQ(test::count_tmp_files(dir.path()), 0);
}

TEST(RunMetadata, InvalidUtf8InMessageIsStillWritten) {
  TempDir dir;
  RunSummary summary = example_summary();
  summary.status = "failed";
  summary.message = "cannot read \xff.stl";
  write_run_json(dir / "run.json", {{"run", to_json(summary)}});
  const auto json = nlohmann::json::parse(read_file(dir / "run.json"));
  EXPECT_EQ(json.at("run").at("status"), "failed");
}

TEST(RunMetadata, UnwritableFolderThrowsRunErrorNamingFile) {
  TempDir dir;
  const auto file = dir / "missing" / "run.json";
  try {
    write_run_json(file, nlohmann::json::object());
    FAIL() << "expected RunError";
  } catch (const RunError& error) {
    EXPECT_NE(std::string(error.what()).find(file.string()), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace partimix::io
