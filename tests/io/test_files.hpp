#pragma once
// Files for the io tests: a fresh folder per test (support/temp_dir.hpp) and leftovers of
// atomic writes.
#include <filesystem>

#include "support/temp_dir.hpp"

namespace partimix::test {

using test_support::read_file;
using test_support::TempDir;

// Files in folder whose name ends in ".tmp" (left over from an interrupted atomic write).
inline int count_tmp_files(const std::filesystem::path& folder) {
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    count += entry.path().extension() == ".tmp" ? 1 : 0;
  }
  return count;
}

}  // namespace partimix::test
