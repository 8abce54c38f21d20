// Kill and resume (docs/architecture-notes.md, "Checkpoints"): a run killed with SIGKILL at
// seeded random moments and resumed from its checkpoints ends with the same series.csv, frames,
// collection and figures, bit for bit, as the run that was never stopped (serial), for an SPH
// mixer, an incompressible SPH plate and a DEM drum; the DEM drum killed and resumed on two threads
// is bit for bit the serial run that was never stopped (docs/dem.md, "The solver"). After every
// kill the output folder is consistent without resuming: whole rows, a collection of complete
// frames, a valid run.json that says the run did not finish and how far it had come.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include "app/cli_support.hpp"

namespace partimix::cli_test {
namespace {

using ::testing::HasSubstr;

struct KillCase {
  std::string file;  // in cases/
  std::vector<std::string> settings;
  std::string method;
};

std::vector<std::string> run_arguments(const KillCase& c, const std::string& threads) {
  std::vector<std::string> arguments{
      "run", (fs::path(PARTIMIX_SOURCE_DIR) / "cases" / c.file).string(), "-q", "-t", threads};
  for (const std::string& setting : c.settings) {
    arguments.push_back("--set");
    arguments.push_back(setting);
  }
  return arguments;
}

std::vector<std::string> with(std::vector<std::string> arguments,
                              const std::vector<std::string>& more) {
  arguments.insert(arguments.end(), more.begin(), more.end());
  return arguments;
}

bool has_checkpoint(const fs::path& out) {
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(out / "checkpoints", error)) {
    if (entry.path().extension() == ".h5")
      return true;
  }
  return false;
}

// What a killed run's folder must be: every series row whole, every listed frame complete (a
// frame is written to a temporary name and renamed), run.json valid and "running".
void expect_consistent(const fs::path& out, const std::string& method) {
  const std::string series = read_file(out / "series.csv");
  ASSERT_FALSE(series.empty());
  EXPECT_EQ(series.back(), '\n') << "a half-written row";
  const std::size_t columns = std::count(series.begin(), series.begin() + series.find('\n'), ',');
  std::istringstream lines(series);
  for (std::string line; std::getline(lines, line);)
    EXPECT_EQ(static_cast<std::size_t>(std::count(line.begin(), line.end(), ',')), columns) << line;
  if (fs::exists(out / (method + ".pvd"))) {
    for (const FrameEntry& frame : read_pvd(out / (method + ".pvd"))) {
      const std::string text = read_file(out / frame.file);
      EXPECT_TRUE(text.ends_with("</VTKFile>\n")) << frame.file << " is not complete";
    }
  }
  const nlohmann::json run = read_json(out / "run.json");
  EXPECT_EQ(run.at("run").at("status"), "running");
  // run.json follows every frame and checkpoint: past the first checkpoint it has steps.
  EXPECT_GT(run.at("run").at("steps").get<int>(), 0) << "run.json is not updated as the run goes";
}

// Starts the run (or resumes it once it has a checkpoint) and kills it with SIGKILL a seeded
// random time after its first checkpoint, `kills` times; then resumes it to the end.
void kill_and_resume(const Scratch& scratch, const KillCase& c, const std::string& threads,
                     int kills, std::uint32_t seed) {
  std::mt19937 random(seed);
  std::uniform_int_distribution<int> delay_ms(0, 1500);
  const fs::path out = scratch.work() / "killed";
  for (int k = 0; k < kills; ++k) {
    const bool resume = has_checkpoint(out);
    Child child(scratch,
                with(run_arguments(c, threads), {resume ? "--resume" : "--out", out.string()}));
    const auto deadline = Clock::now() + kTimeLimit;
    while (!has_checkpoint(out) && Clock::now() < deadline)
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    std::this_thread::sleep_for(std::chrono::milliseconds(delay_ms(random)));
    child.signal(SIGKILL);
    const Outcome outcome = child.wait();
    if (outcome.exit_code == 0)
      return;  // it finished before the kill: nothing left to resume
    ASSERT_EQ(outcome.exit_code, 128 + SIGKILL) << outcome.err;
    expect_consistent(out, c.method);
  }
  const Outcome outcome =
      run_partimix(scratch, with(run_arguments(c, threads), {"--resume", out.string()}));
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  EXPECT_THAT(outcome.err, HasSubstr("resuming from"));
}

// The same bytes in every output of the two runs (wall times and the checkpoint's name aside).
void expect_identical_outputs(const fs::path& a, const fs::path& b, const std::string& method) {
  EXPECT_EQ(read_file(a / "series.csv"), read_file(b / "series.csv"));
  EXPECT_EQ(read_file(a / (method + ".pvd")), read_file(b / (method + ".pvd")));
  EXPECT_EQ(frame_files(a), frame_files(b));
  for (const std::string& frame : frame_files(a))
    EXPECT_TRUE(read_file(a / frame) == read_file(b / frame)) << frame << " differs";
  const nlohmann::json run_a = read_json(a / "run.json");
  const nlohmann::json run_b = read_json(b / "run.json");
  EXPECT_EQ(run_a.at("figures"), run_b.at("figures"));
  EXPECT_EQ(run_a.at("run").at("steps"), run_b.at("run").at("steps"));
  EXPECT_EQ(run_b.at("run").at("status"), "completed");
}

// The seed's planetary mixer in CMC, coarse (6,800 particles), 0.025 s (about 50 steps; a few
// seconds, under the sanitizers about half a minute): moving impeller, power and mixing
// analyses.
const KillCase kMixer{"bohl_planetary_cmc.yaml",
                      {"sph.spacing=0.01", "time.end=0.025", "time.sample_interval=0.0025",
                       "time.output_interval=0.005", "time.checkpoint_interval=0.0025"},
                      "sph"};

// The seed's validation drum with 300 grains, 0.8 s turning: contact histories, moving walls,
// the mixing, repose and profile analyses.
const KillCase kDrum{
    "drum_validation.yaml",
    {"dem.fill.count=300", "dem.fill.settle_time=0.2", "time.end=0.8", "time.sample_interval=0.02",
     "time.output_interval=0.1", "time.checkpoint_interval=0.05"},
    "dem"};

// The 2D rotating plate with the incompressible scheme, implicit viscosity and the extrapolated
// ghost velocity at dp = 7.5 mm, 0.5 s (about 220 steps, 2-3 s): the projection's step starts
// from the grid and wall state of the last one, which a resumed run must rebuild.
const KillCase kPlate{"rotating_plate_2d.yaml",
                      {"sph.spacing=0.0075", "sph.wall_velocity=extrapolated", "time.end=0.5",
                       "time.output_interval=0.1", "time.checkpoint_interval=0.05"},
                      "sph"};

// Runs case `c` whole and killed three times (seeded), serially, and compares the outputs.
void expect_killed_run_is_the_whole_one(const KillCase& c, std::uint32_t seed) {
  const Scratch scratch;
  const Outcome reference = run_partimix(
      scratch, with(run_arguments(c, "1"), {"--out", (scratch.work() / "whole").string()}));
  ASSERT_EQ(reference.exit_code, 0) << reference.err;
  kill_and_resume(scratch, c, "1", 3, seed);
  expect_identical_outputs(scratch.work() / "whole", scratch.work() / "killed", c.method);
}

TEST(KillAndResume, MixerIsBitwiseTheUninterruptedRun) {
  expect_killed_run_is_the_whole_one(kMixer, 14);
}

TEST(KillAndResume, IncompressiblePlateIsBitwiseTheUninterruptedRun) {
  expect_killed_run_is_the_whole_one(kPlate, 21);
}

TEST(KillAndResume, DrumIsBitwiseTheUninterruptedRun) {
  expect_killed_run_is_the_whole_one(kDrum, 5);
}

TEST(KillAndResume, DrumOnTwoThreadsIsBitwiseTheSerialRun) {
  const Scratch scratch;
  // Threads that wait without spinning, as ctest runs two tests side by side on two cores.
  ::setenv("OMP_WAIT_POLICY", "passive", 1);
  const Outcome reference = run_partimix(
      scratch, with(run_arguments(kDrum, "1"), {"--out", (scratch.work() / "whole").string()}));
  ASSERT_EQ(reference.exit_code, 0) << reference.err;
  kill_and_resume(scratch, kDrum, "2", 2, 7);
  expect_identical_outputs(scratch.work() / "whole", scratch.work() / "killed", "dem");
}

// Ctrl-C writes a checkpoint before the frame of the moment it stopped; the resumed run drops
// that frame and row (they are off the schedule) and ends as the uninterrupted run.
TEST(KillAndResume, CtrlCLeavesACheckpointToResumeFrom) {
  const Scratch scratch;
  KillCase drum = kDrum;
  drum.settings.back() = "time.checkpoint_interval=0";
  ASSERT_EQ(run_partimix(scratch, with(run_arguments(drum, "1"),
                                       {"--out", (scratch.work() / "whole").string()}))
                .exit_code,
            0);
  const fs::path out = scratch.work() / "killed";
  {
    Child child(scratch, with(run_arguments(drum, "1"), {"--out", out.string()}));
    ASSERT_TRUE(wait_for_file(out / "frames" / "dem_000002.vtp"));
    child.signal(SIGINT);
    ASSERT_EQ(child.wait().exit_code, 130);
  }
  ASSERT_TRUE(has_checkpoint(out));
  const Outcome outcome =
      run_partimix(scratch, with(run_arguments(drum, "1"), {"--resume", out.string()}));
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  expect_identical_outputs(scratch.work() / "whole", out, "dem");
}

TEST(Resume, RefusesACheckpointOfAnotherCase) {
  const Scratch scratch;
  const fs::path out = scratch.work() / "out";
  KillCase drum = kDrum;
  drum.settings.push_back("time.end=0.1");
  ASSERT_EQ(
      run_partimix(scratch, with(run_arguments(drum, "1"), {"--out", out.string()})).exit_code, 0);
  drum.settings.push_back("dem.interactions.particle.friction=0.3");
  const Outcome outcome =
      run_partimix(scratch, with(run_arguments(drum, "1"), {"--resume", out.string()}));
  EXPECT_EQ(outcome.exit_code, 2);
  EXPECT_THAT(outcome.err, HasSubstr("dem.interactions.particle.friction"));
  EXPECT_THAT(outcome.err, HasSubstr("checkpoint_"));
}

TEST(Resume, ExtendsARunPastItsEndTime) {
  const Scratch scratch;
  const fs::path out = scratch.work() / "out";
  KillCase drum = kDrum;
  drum.settings.push_back("time.end=0.2");
  ASSERT_EQ(
      run_partimix(scratch, with(run_arguments(drum, "1"), {"--out", out.string()})).exit_code, 0);
  drum.settings.push_back("time.end=0.3");
  const Outcome outcome =
      run_partimix(scratch, with(run_arguments(drum, "1"), {"--resume", out.string()}));
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  const nlohmann::json run = read_json(out / "run.json").at("run");
  EXPECT_NEAR(run.at("simulated_time").get<double>(), 0.3, 1e-9);
}

TEST(Resume, WithoutACheckpointIsABadInput) {
  const Scratch scratch;
  const Outcome outcome = run_partimix(
      scratch, with(run_arguments(kDrum, "1"), {"--resume", (scratch.work() / "none").string()}));
  EXPECT_EQ(outcome.exit_code, 2);
  EXPECT_THAT(outcome.err, HasSubstr("checkpoint"));
}

}  // namespace
}  // namespace partimix::cli_test
