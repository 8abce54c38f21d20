// An output folder keeps what the user put there (issue 15: `run --out DIR` deleted DIR/plots
// and DIR/frames with whatever they held): a run removes only what the manifest lists, and a
// folder of someone else's files needs --overwrite.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>

#include "app/output_folder.hpp"
#include "cli_support.hpp"
#include "core/error.hpp"
#include "dam_break_case.hpp"
#include "support/temp_dir.hpp"

namespace partimix::app {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

void touch(const fs::path& file) {
  fs::create_directories(file.parent_path());
  std::ofstream(file) << "mine";
}

TEST(OutputFolder, ANewFolderIsCreatedWithAnEmptyManifest) {
  const test_support::TempDir dir;
  prepare_output_folder(dir / "out", false);
  EXPECT_TRUE(fs::is_directory(dir / "out"));
  EXPECT_EQ(test_support::read_file(dir / "out" / kManifestName), "");
}

TEST(OutputFolder, AFolderOfSomeoneElsesFilesIsRefusedAndLeftAlone) {
  const test_support::TempDir dir;
  touch(dir / "out" / "plots" / "my_figure.png");
  try {
    prepare_output_folder(dir / "out", false);
    FAIL() << "a folder of user files was taken";
  } catch (const InputError& error) {
    EXPECT_EQ(error.location().key_path, "--out");
    EXPECT_THAT(error.message(), HasSubstr("--overwrite"));
  }
  EXPECT_TRUE(fs::exists(dir / "out" / "plots" / "my_figure.png"));
  EXPECT_FALSE(fs::exists(dir / "out" / kManifestName));
}

TEST(OutputFolder, OverwriteWritesIntoItRemovingNothing) {
  const test_support::TempDir dir;
  touch(dir / "out" / "frames" / "notes.txt");
  prepare_output_folder(dir / "out", true);
  EXPECT_TRUE(fs::exists(dir / "out" / "frames" / "notes.txt"));
  EXPECT_TRUE(fs::exists(dir / "out" / kManifestName));
}

TEST(OutputFolder, OnlyTheListedFilesAndEmptiedFoldersGo) {
  const test_support::TempDir dir;
  const fs::path out = dir / "out";
  prepare_output_folder(out, false);
  for (const char* file : {"series.csv", "frames/sph_000000.vtp", "plots/overview.png"})
    touch(out / file);
  for (const char* listed : {"series.csv", "frames", "frames/sph_000000.vtp", "plots",
                             "plots/overview.png", "../outside.txt", "/etc/hostname"}) {
    record_output(out, listed);
  }
  touch(out / "plots" / "my_figure.png");
  touch(out / "readme.txt");
  touch(dir / "outside.txt");
  prepare_output_folder(out, false);
  EXPECT_FALSE(fs::exists(out / "series.csv"));
  EXPECT_FALSE(fs::exists(out / "frames"));
  EXPECT_FALSE(fs::exists(out / "plots" / "overview.png"));
  EXPECT_TRUE(fs::exists(out / "plots" / "my_figure.png"));
  EXPECT_TRUE(fs::exists(out / "readme.txt"));
  EXPECT_TRUE(fs::exists(dir / "outside.txt")) << "a path outside the folder was followed";
}

TEST(OutputFolder, AListedFolderWithAManifestIsClearedByIt) {
  const test_support::TempDir dir;
  const fs::path sweep = dir / "sweep";
  prepare_output_folder(sweep, false);
  prepare_output_folder(sweep / "run_000", false);
  touch(sweep / "run_000" / "series.csv");
  touch(sweep / "run_000" / "log.txt");
  record_output(sweep / "run_000", "series.csv");
  record_output(sweep, "run_000");
  record_output(sweep, "run_000/log.txt");
  prepare_output_folder(sweep, false);
  EXPECT_FALSE(fs::exists(sweep / "run_000"));
}

}  // namespace
}  // namespace partimix::app

namespace partimix::cli_test {
namespace {

using ::testing::HasSubstr;

class OutputFolderRun : public ::testing::Test {
 protected:
  void SetUp() override { scratch_.write("case.yaml", kDamBreak3D); }
  Outcome run(std::vector<std::string> extra = {}) {
    std::vector<std::string> arguments{"run", "case.yaml", "--out", "out", "-q", "-t", "1"};
    arguments.insert(arguments.end(), extra.begin(), extra.end());
    return run_partimix(scratch_, arguments);
  }
  Scratch scratch_;
};

TEST_F(OutputFolderRun, ARerunKeepsTheUsersFilesAndReplacesItsOwn) {
  ASSERT_EQ(run().exit_code, 0);
  ASSERT_EQ(run_partimix(scratch_, {"plot", "out"}).exit_code, 0);
  const fs::path out = scratch_.work() / "out";
  std::ofstream(out / "frames" / "my_notes.txt") << "mine";
  std::ofstream(out / "plots" / "my_figure.png") << "mine";
  const Outcome again = run();
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_TRUE(fs::exists(out / "frames" / "my_notes.txt"));
  EXPECT_TRUE(fs::exists(out / "plots" / "my_figure.png"));
  EXPECT_FALSE(fs::exists(out / "plots" / "overview.png")) << "a stale plot of the earlier run";
  EXPECT_TRUE(fs::exists(out / "series.csv"));
}

TEST_F(OutputFolderRun, AFolderOfOtherFilesNeedsOverwrite) {
  fs::create_directories(scratch_.work() / "out");
  std::ofstream(scratch_.work() / "out" / "thesis.tex") << "mine";
  const Outcome refused = run();
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_THAT(refused.err, HasSubstr("error: out: --out: the output folder holds files"));
  EXPECT_FALSE(fs::exists(scratch_.work() / "out" / "series.csv"));
  const Outcome accepted = run({"--overwrite"});
  EXPECT_EQ(accepted.exit_code, 0) << accepted.err;
  EXPECT_TRUE(fs::exists(scratch_.work() / "out" / "thesis.tex"));
  EXPECT_TRUE(fs::exists(scratch_.work() / "out" / "series.csv"));
}

}  // namespace
}  // namespace partimix::cli_test
