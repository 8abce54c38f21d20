#pragma once
// The sub-commands of `partimix`. Each returns the process exit code (core/error.hpp).
#include <filesystem>
#include <string>
#include <vector>

namespace partimix::app {

struct RunArguments {
  std::string case_file;
  std::filesystem::path output_dir;  // empty: out/<case name>
  std::vector<std::string> overrides;
  int threads = 0;  // 0: all cores
  bool quiet = false;
  bool overwrite = false;            // write into a folder that holds files partimix did not write
  std::filesystem::path resume_dir;  // non-empty: resume the run in this folder (and write there)
};

int run_command(const RunArguments& arguments);
int check_command(const std::string& case_file, const std::vector<std::string>& overrides);
int plot_command(const std::filesystem::path& output_dir);
// Writes each wall generated as a mesh (a truck drum) as <output_dir>/wall_<k>.stl.
int stl_command(const std::string& case_file, const std::vector<std::string>& overrides,
                const std::filesystem::path& output_dir);

}  // namespace partimix::app
