#pragma once
// A fresh folder for one test, unique per test and process (so parallel ctest runs and build
// folders do not collide), removed with the object; and reading a whole file.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace partimix::test_support {

class TempDir {
 public:
  // `prefix` keeps apart the folders of helpers that one test may use together.
  explicit TempDir(const std::string& prefix = "partimix")
      : path_(std::filesystem::temp_directory_path() / unique_name(prefix)) {
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

 private:
  static std::string unique_name(const std::string& prefix) {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    return prefix + "_" + info->test_suite_name() + "_" + info->name() + "_" +
           std::to_string(::getpid());
  }

  std::filesystem::path path_;
};

inline std::string read_file(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace partimix::test_support
