// Ctrl-C (SIGINT) ends a run cleanly: exit code 130, run.json says "interrupted", and the frame
// of the moment it stopped is written and listed.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <csignal>
#include <string>
#include <vector>

#include "cli_support.hpp"
#include "grains_case.hpp"

namespace partimix::cli_test {
namespace {

using ::testing::ElementsAreArray;
using ::testing::HasSubstr;

// Still water in a small 2D tank with an end time far beyond what the test waits for.
const std::string kLongTank = R"(name: long_tank
solver: sph
dimensions: 2
gravity: [0, -9.81]
domain:
  min: [-0.1, -0.1]
  max: [0.5, 0.4]
time:
  end: 1000
  output_interval: 0.01
sph:
  spacing: 0.02
fluid:
  density: 1000
  viscosity: 1.0e-3
  regions:
    - shape: box
      min: [0, 0]
      max: [0.4, 0.1]
walls:
  - shape: box
    min: [0, 0]
    max: [0.4, 0.3]
    open: [y+]
)";

// SIGINT (Ctrl-C) and SIGTERM (a batch system, `kill`) end a run the same way.
class Interrupt : public ::testing::TestWithParam<int> {};

TEST_P(Interrupt, EndsTheRunWithTheCurrentFrame) {
  const Scratch scratch;
  scratch.write("case.yaml", kLongTank);
  const fs::path out = scratch.work() / "out";
  Child child(scratch, {"run", "case.yaml", "--out", "out", "-q", "-t", "1"});
  // The third frame means steps ran, and run.json has followed the second.
  ASSERT_TRUE(wait_for_file(out / "frames" / "sph_000002.vtp"));
  const nlohmann::json running = read_json(out / "run.json").at("run");
  EXPECT_EQ(running.at("status"), "running");
  EXPECT_GT(running.at("steps").get<int>(), 0) << "run.json is not updated at every frame";
  EXPECT_GE(running.at("simulated_time").get<double>(), 0.01 - 1e-9);
  child.signal(GetParam());
  const Outcome outcome = child.wait();
  EXPECT_EQ(outcome.exit_code, 130) << outcome.err;
  EXPECT_THAT(outcome.err, HasSubstr("interrupted at step "));
  const nlohmann::json run = read_json(out / "run.json").at("run");
  EXPECT_EQ(run.at("status"), "interrupted");
  EXPECT_THAT(run.at("message").get<std::string>(), HasSubstr("interrupted at step "));
  const double stopped_at = run.at("simulated_time");
  EXPECT_GT(stopped_at, 0.0);
  EXPECT_LT(stopped_at, 1000.0);
  const std::vector<FrameEntry> frames = read_pvd(out / "sph.pvd");
  ASSERT_GE(frames.size(), 2u);
  EXPECT_EQ(frames.back().time, stopped_at);
  EXPECT_TRUE(fs::exists(out / frames.back().file));
  EXPECT_THAT(frame_files(out), ElementsAreArray(files_of(frames)));
}

INSTANTIATE_TEST_SUITE_P(Signals, Interrupt, ::testing::Values(SIGINT, SIGTERM),
                         [](const auto& variant) {
                           return variant.param == SIGINT ? "Sigint" : "Sigterm";
                         });

// Grains settling for a long time before the run: Ctrl-C ends the settling, and nothing is
// written (the run has not started).
TEST(InterruptSettling, SigintEndsTheSettlingAndWritesNothing) {
  const Scratch scratch;
  scratch.write("case.yaml", replaced(kGrainsInABox, "settle_time: 0.05",
                                      "settle_time: 1000\n    settle_energy: 1.0e-30"));
  Child child(scratch, {"run", "case.yaml", "--out", "out", "-t", "1"});
  const auto deadline = Clock::now() + kTimeLimit;
  while (read_file(scratch.logs() / "stderr.txt").find("settling") == std::string::npos &&
         Clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  child.signal(SIGINT);
  const Outcome outcome = child.wait();
  EXPECT_EQ(outcome.exit_code, 130) << outcome.err;
  EXPECT_THAT(outcome.err, HasSubstr("interrupted while settling the grains"));
  EXPECT_THAT(outcome.err, HasSubstr("nothing was written"));
  EXPECT_FALSE(fs::exists(scratch.work() / "out"));
}

}  // namespace
}  // namespace partimix::cli_test
