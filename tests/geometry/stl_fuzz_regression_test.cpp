// Findings of fuzz/case_loader_fuzz (fuzz/README.md) in the STL reader: a mesh `file` that names
// a folder (as `file: ""` does, the case's own folder) or a device that never ends must be an
// InputError naming the file, not an exception of the stream library or a read without end.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "core/error.hpp"
#include "geometry/stl_reader.hpp"
#include "support/temp_dir.hpp"

namespace partimix::geometry {
namespace {

using test_support::TempDir;
using ::testing::HasSubstr;

void expect_not_a_regular_file(const std::string& path) {
  try {
    read_stl(path);
    FAIL() << "read_stl(" << path << ") returned";
  } catch (const InputError& error) {
    EXPECT_EQ(error.location().file, path);
    EXPECT_THAT(error.message(), HasSubstr("not a regular file"));
  }
}

TEST(StlFuzzRegression, FolderIsAnInputError) {
  const TempDir dir("stl_fuzz");
  expect_not_a_regular_file(dir.path().string());
  expect_not_a_regular_file((dir.path() / "").string());
}

// /dev/zero exists on every Linux the project builds on (Debian 12).
TEST(StlFuzzRegression, EndlessDeviceIsAnInputError) {
  expect_not_a_regular_file("/dev/zero");
}

TEST(StlFuzzRegression, MissingFileStillSaysSo) {
  const TempDir dir("stl_fuzz");
  try {
    read_stl((dir / "nowhere.stl").string());
    FAIL() << "read_stl returned";
  } catch (const InputError& error) {
    EXPECT_THAT(error.message(), HasSubstr("no such readable file"));
  }
}

}  // namespace
}  // namespace partimix::geometry
