// A run that fails exits with code 1 and says why (which particle, at which step and time),
// run.json says "failed" with that message, and the frames written before the failure stay.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "cli_support.hpp"

namespace partimix::cli_test {
namespace {

using ::testing::ContainsRegex;
using ::testing::ElementsAreArray;
using ::testing::HasSubstr;

// A block of water with no walls falls out through the bottom of the domain after about
// 0.08 s (260 steps of 100 particles).
const std::string kFallingBlock = R"(name: falling_block
solver: sph
dimensions: 2
gravity: [0, -9.81]
domain:
  min: [-0.1, -0.02]
  max: [0.3, 0.3]
time:
  end: 1.0
  output_interval: 0.02
sph:
  spacing: 0.02
fluid:
  density: 1000
  viscosity: 1.0e-3
  regions:
    - shape: box
      min: [0, 0]
      max: [0.2, 0.2]
)";

// A 2D dam break whose Tait exponent (1e6) overflows the pressure of the hydrostatically
// compressed fluid: infinite accelerations, then non-finite values after the first steps.
const std::string kUnstableDamBreak = R"(name: unstable_dam_break
solver: sph
dimensions: 2
gravity: [0, -9.81]
domain:
  min: [-0.1, -0.1]
  max: [0.7, 0.5]
time:
  end: 1.0
  output_interval: 0.01
sph:
  spacing: 0.02
  tait_gamma: 1.0e6
fluid:
  density: 1000
  viscosity: 1.0e-3
  regions:
    - shape: box
      min: [0, 0]
      max: [0.2, 0.2]
walls:
  - shape: box
    min: [0, 0]
    max: [0.6, 0.4]
    open: [y+]
)";

const std::vector<std::string> kRun{"run", "case.yaml", "--out", "out", "-q", "-t", "1"};

// Exit code 1; stderr and run.json give the reason, which names `what`; the frames before the
// failure (at least `kept_frames`) are kept and listed, and none is written after it.
void expect_failed_run(const Scratch& scratch, const Outcome& outcome, const std::string& what,
                       std::size_t kept_frames) {
  EXPECT_EQ(outcome.exit_code, 1) << outcome.err;
  EXPECT_THAT(outcome.err,
              ContainsRegex("step [0-9]+, t = [0-9.e+-]+ s: particle [0-9]+ at \\(.*\\) " + what));
  const fs::path out = scratch.work() / "out";
  const nlohmann::json run = read_json(out / "run.json").at("run");
  EXPECT_EQ(run.at("status"), "failed");
  const std::string message = run.at("message");
  EXPECT_THAT(message, HasSubstr(what));
  EXPECT_THAT(outcome.err, HasSubstr(message));
  const std::vector<FrameEntry> frames = read_pvd(out / "sph.pvd");
  EXPECT_GE(frames.size(), kept_frames);
  EXPECT_THAT(frame_files(out), ElementsAreArray(files_of(frames)));
  for (const auto& frame : frames) {
    EXPECT_LT(frame.time, run.at("simulated_time").get<double>()) << frame.file;
  }
}

TEST(RunFailure, ParticleLeavingTheDomainStopsTheRun) {
  const Scratch scratch;
  scratch.write("case.yaml", kFallingBlock);
  expect_failed_run(scratch, run_partimix(scratch, kRun), "left the domain", 2);
}

TEST(RunFailure, BlowUpToNonFiniteValuesStopsTheRun) {
  const Scratch scratch;
  scratch.write("case.yaml", kUnstableDamBreak);
  expect_failed_run(scratch, run_partimix(scratch, kRun), "has a non-finite", 1);
}

// An output folder that cannot be created (here: below a regular file) is an I/O failure of the
// run: exit code 1 with a message naming the folder, not a crash.
TEST(RunFailure, OutputFolderThatCannotBeCreatedFailsTheRun) {
  const Scratch scratch;
  scratch.write("case.yaml", kFallingBlock);
  const Outcome outcome =
      run_partimix(scratch, {"run", "case.yaml", "--out", "case.yaml/out", "-q", "-t", "1"});
  EXPECT_EQ(outcome.exit_code, 1) << outcome.err;
  EXPECT_THAT(outcome.err, HasSubstr("case.yaml/out"));
}

// A write that fails (here a frame larger than the process may write, as on a full disk) stops
// the run with the system's reason, and run.json says so.
TEST(RunFailure, AFailedWriteNamesTheReason) {
  const Scratch scratch;
  scratch.write("case.yaml", replaced(kFallingBlock, "spacing: 0.02", "spacing: 0.004"));
  const Outcome outcome = Child(scratch, kRun, 40000).wait();
  EXPECT_EQ(outcome.exit_code, 1) << outcome.err;
  EXPECT_THAT(outcome.err, HasSubstr("failed writing 'out/frames/sph_000000.vtp': File too large"));
  const nlohmann::json run = read_json(scratch.work() / "out" / "run.json").at("run");
  EXPECT_EQ(run.at("status"), "failed");
  EXPECT_THAT(run.at("message").get<std::string>(), HasSubstr("File too large"));
  EXPECT_FALSE(fs::exists(scratch.work() / "out" / "frames" / "sph_000000.vtp"));
}

}  // namespace
}  // namespace partimix::cli_test
