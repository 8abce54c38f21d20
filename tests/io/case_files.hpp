#pragma once
// Helpers for the case-loader tests: a minimal valid case, line edits, temp files, and the
// InputError a load throws.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "core/error.hpp"
#include "io/case.hpp"
#include "support/temp_dir.hpp"

namespace partimix::case_test {

// A valid 2D case with only the required keys; the line numbers are used by the error tests.
inline const std::string kMinimal2D = R"(solver: sph
dimensions: 2
domain:
  min: [0, 0]
  max: [1.6, 1.0]
time:
  end: 1.0
  output_interval: 0.02
sph:
  spacing: 0.01
fluid:
  density: 1000
  viscosity: 1.0e-3
  regions:
    - shape: box
      min: [0, 0]
      max: [0.5, 1.0]
)";

// A valid 3D case with a default tracer and the analyses list `items`; the first item is line
// kFirstAnalysis3D.
inline std::string with_analyses_3d(const std::string& items) {
  return R"(solver: sph
dimensions: 3
domain:
  min: [0, 0, 0]
  max: [1, 1, 1]
time:
  end: 1.0
  output_interval: 0.1
sph:
  spacing: 0.05
fluid:
  density: 1000
  viscosity: 1.0e-3
  tracer: {}
  regions:
    - shape: box
      min: [0, 0, 0]
      max: [1, 1, 0.5]
analyses:
)" + items;
}
inline constexpr int kFirstAnalysis3D = 20;

inline std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    lines.push_back(line);
  }
  return lines;
}

inline std::string joined(const std::vector<std::string>& lines) {
  std::string text;
  for (const std::string& line : lines) {
    text += line + "\n";
  }
  return text;
}

// `text` with its 1-based line `number` replaced by `line`.
inline std::string replace_line(const std::string& text, std::size_t number,
                                const std::string& line) {
  std::vector<std::string> lines = lines_of(text);
  lines.at(number - 1) = line;
  return joined(lines);
}

// `text` with `line` inserted so that it becomes line `number`.
inline std::string insert_line(const std::string& text, std::size_t number,
                               const std::string& line) {
  std::vector<std::string> lines = lines_of(text);
  lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(number - 1), line);
  return joined(lines);
}

inline std::string remove_line(const std::string& text, std::size_t number) {
  std::vector<std::string> lines = lines_of(text);
  lines.erase(lines.begin() + static_cast<std::ptrdiff_t>(number - 1));
  return joined(lines);
}

// A case file `case.yaml` in a folder of its own under the temp folder (unique per test and
// process), removed with the object.
class CaseFile {
 public:
  explicit CaseFile(const std::string& text) : folder_("partimix_case") {
    std::ofstream(folder_ / "case.yaml") << text;
  }

  std::string path() const { return (folder_ / "case.yaml").string(); }

  // Writes `bytes` to the file `name` beside the case file (a mesh the case names); its path.
  std::string add_file(const std::string& name, const std::string& bytes) const {
    std::ofstream(folder_ / name, std::ios::binary) << bytes;
    return (folder_ / name).string();
  }

 private:
  test_support::TempDir folder_;
};

inline io::Case load_text(const std::string& text, const std::vector<std::string>& overrides = {}) {
  const CaseFile file(text);
  return io::load_case(file.path(), overrides);
}

// The InputError that loading `file` throws; a test failure when none is thrown.
inline InputError load_error(const CaseFile& file, const std::vector<std::string>& overrides = {}) {
  try {
    io::load_case(file.path(), overrides);
  } catch (const InputError& error) {
    return error;
  }
  ADD_FAILURE() << "expected an InputError";
  return InputError({}, "");
}

inline InputError load_error(const std::string& text,
                             const std::vector<std::string>& overrides = {}) {
  return load_error(CaseFile(text), overrides);
}

// Checks the location of `error`; file "case.yaml" stands for the test's case file.
inline void expect_location(const InputError& error, const std::string& file, int line, int column,
                            const std::string& key_path) {
  if (file == "case.yaml") {
    EXPECT_EQ(std::filesystem::path(error.location().file).filename(), file) << error.what();
  } else {
    EXPECT_EQ(error.location().file, file) << error.what();
  }
  EXPECT_EQ(error.location().line, line) << error.what();
  EXPECT_EQ(error.location().column, column) << error.what();
  EXPECT_EQ(error.location().key_path, key_path) << error.what();
}

}  // namespace partimix::case_test
