#pragma once
// Running a Python script of tools/ in a child process, for the tests of those scripts: its exit
// code and what it wrote to stdout and stderr.
#include <string>
#include <vector>

#include "app/child_process.hpp"
#include "support/temp_dir.hpp"

namespace partimix::app {

struct ScriptOutcome {
  int exit_code = -1;
  std::string output;  // stdout and stderr
};

// Runs /usr/bin/python3 tools/<script> with `arguments`, its output logged in dir/log.txt.
inline ScriptOutcome run_tool_script(const test_support::TempDir& dir, const std::string& script,
                                     const std::vector<std::string>& arguments) {
  std::vector<std::string> argv{"/usr/bin/python3",
                                std::string(PARTIMIX_SOURCE_DIR) + "/tools/" + script};
  argv.insert(argv.end(), arguments.begin(), arguments.end());
  const int code = wait_process(start_process(argv, dir / "log.txt"));
  return {code, test_support::read_file(dir / "log.txt")};
}

}  // namespace partimix::app
