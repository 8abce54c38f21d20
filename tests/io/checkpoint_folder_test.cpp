// The checkpoint folder of a run: names with the step, only the newest two kept (by step, not
// by file time), and resuming from the newest one that reads, else the one before it.
#include "io/checkpoint_folder.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <set>
#include <string>

#include "core/error.hpp"
#include "io/test_files.hpp"

namespace partimix::io {
namespace {

using test::read_file;
using test::TempDir;

StateArchive state_at(std::uint64_t step) {
  StateArchive archive;
  archive.put_integers("step", std::vector<std::int64_t>{static_cast<std::int64_t>(step)});
  return archive;
}

std::set<std::string> names_in(const std::filesystem::path& folder) {
  std::set<std::string> names;
  for (const auto& item : std::filesystem::directory_iterator(folder)) {
    names.insert(item.path().filename().string());
  }
  return names;
}

void write_bytes(const std::filesystem::path& file, const std::string& bytes) {
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out << bytes;
}

void truncate_to_half(const std::filesystem::path& file) {
  const std::string bytes = read_file(file);
  write_bytes(file, bytes.substr(0, bytes.size() / 2));
}

TEST(CheckpointFolder, NamesFilesByStepWithTwelveDigits) {
  EXPECT_EQ(CheckpointFolder::file_name(42), "checkpoint_000000000042.h5");
  EXPECT_EQ(CheckpointFolder::file_name(12345678901234), "checkpoint_12345678901234.h5");
  const TempDir dir;
  const CheckpointFolder folder(dir / "out/checkpoints");
  const std::filesystem::path written = folder.write(42, state_at(42));
  EXPECT_EQ(written, dir / "out/checkpoints/checkpoint_000000000042.h5");
  EXPECT_TRUE(std::filesystem::is_regular_file(written));
}

TEST(CheckpointFolder, KeepsTheNewestTwoByStep) {
  const TempDir dir;
  const CheckpointFolder folder(dir.path());
  for (const std::uint64_t step : {100, 300, 200, 400}) {
    folder.write(step, state_at(step));
  }
  EXPECT_EQ(names_in(dir.path()),
            (std::set<std::string>{"checkpoint_000000000300.h5", "checkpoint_000000000400.h5"}));
}

TEST(CheckpointFolder, RemovesLeftoverTemporariesAndLeavesOtherFiles) {
  const TempDir dir;
  write_bytes(dir / "checkpoint_000000000007.h5.tmp", "half");
  write_bytes(dir / "notes.txt", "mine");
  write_bytes(dir / "checkpoint_5.h5", "not named by partimix");
  const CheckpointFolder folder(dir.path());
  folder.write(1, state_at(1));
  folder.write(2, state_at(2));
  folder.write(3, state_at(3));
  EXPECT_EQ(names_in(dir.path()),
            (std::set<std::string>{"checkpoint_000000000002.h5", "checkpoint_000000000003.h5",
                                   "notes.txt", "checkpoint_5.h5"}));
}

// Past twelve digits the names no longer sort as text: the step decides.
TEST(CheckpointFolder, LatestIsTheLargestStep) {
  const TempDir dir;
  const CheckpointFolder folder(dir.path());
  EXPECT_FALSE(folder.latest().has_value());
  EXPECT_FALSE(CheckpointFolder(dir / "missing").latest().has_value());
  const std::uint64_t big = 10'000'000'000'000;
  folder.write(big, state_at(big));
  folder.write(999'999'999'999, state_at(999'999'999'999));
  EXPECT_EQ(folder.latest(), dir / CheckpointFolder::file_name(big));
  std::filesystem::path used;
  EXPECT_EQ(folder.read_latest(&used).integers("step")[0], static_cast<std::int64_t>(big));
  EXPECT_EQ(used, dir / CheckpointFolder::file_name(big));
}

TEST(CheckpointFolder, ReadsTheNewest) {
  const TempDir dir;
  const CheckpointFolder folder(dir.path());
  folder.write(10, state_at(10));
  folder.write(20, state_at(20));
  std::filesystem::path used;
  EXPECT_EQ(folder.read_latest(&used).integers("step")[0], 20);
  EXPECT_EQ(used, dir / "checkpoint_000000000020.h5");
  EXPECT_EQ(folder.read_latest().integers("step")[0], 20);
}

TEST(CheckpointFolder, FallsBackToTheOlderWhenTheNewestIsDamaged) {
  const TempDir dir;
  const CheckpointFolder folder(dir.path());
  folder.write(10, state_at(10));
  folder.write(20, state_at(20));
  truncate_to_half(dir / "checkpoint_000000000020.h5");
  std::filesystem::path used;
  EXPECT_EQ(folder.read_latest(&used).integers("step")[0], 10);
  EXPECT_EQ(used, dir / "checkpoint_000000000010.h5");
  EXPECT_EQ(folder.latest(), dir / "checkpoint_000000000020.h5");
  folder.remove_newer_than(used);
  EXPECT_EQ(folder.latest(), dir / "checkpoint_000000000010.h5");
}

TEST(CheckpointFolder, ThrowsTheNewestErrorWhenNoneReads) {
  const TempDir dir;
  const CheckpointFolder folder(dir.path());
  folder.write(10, state_at(10));
  folder.write(20, state_at(20));
  truncate_to_half(dir / "checkpoint_000000000010.h5");
  write_bytes(dir / "checkpoint_000000000020.h5", "");
  try {
    folder.read_latest();
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_EQ(error.location().file, (dir / "checkpoint_000000000020.h5").string());
    EXPECT_NE(error.message().find("empty"), std::string::npos) << error.what();
  }
}

TEST(CheckpointFolder, EmptyOrMissingFolderHasNoCheckpoint) {
  const TempDir dir;
  for (const auto& path : {dir.path(), dir / "missing"}) {
    try {
      CheckpointFolder(path).read_latest();
      FAIL() << "no error for " << path;
    } catch (const InputError& error) {
      EXPECT_EQ(error.location().file, path.string());
      EXPECT_NE(error.message().find("no checkpoint"), std::string::npos) << error.what();
    }
  }
}

TEST(CheckpointFolder, FolderThatCannotBeCreatedGivesRunError) {
  const TempDir dir;
  write_bytes(dir / "plain_file", "x");
  EXPECT_THROW(CheckpointFolder(dir / "plain_file/checkpoints").write(1, state_at(1)), RunError);
}

}  // namespace
}  // namespace partimix::io
