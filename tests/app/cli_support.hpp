#pragma once
// Helpers for the end-to-end tests of the partimix program (PARTIMIX_BINARY): a scratch folder
// per test, the program run in a child process with its stdout, stderr and exit code captured,
// and readers for what a run writes (series.csv, <method>.pvd, run.json).
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "support/temp_dir.hpp"

namespace partimix::cli_test {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// Long enough for any run of these tests, short enough that a hung program fails the test.
inline constexpr std::chrono::seconds kTimeLimit{60};

using test_support::read_file;

// `text` with the first `from` replaced by `to`; a test failure when `from` is not in it.
inline std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  if (at == std::string::npos) {
    ADD_FAILURE() << "'" << from << "' is not in the case text";
    return text;
  }
  return text.replace(at, from.size(), to);
}

// The 1-based number of the first line of `text` that contains `needle` (0 if none does).
inline int line_of(const std::string& text, const std::string& needle) {
  std::istringstream in(text);
  int number = 1;
  for (std::string line; std::getline(in, line); ++number) {
    if (line.find(needle) != std::string::npos)
      return number;
  }
  return 0;
}

// A folder unique per test and process, removed afterwards. work() is the program's working
// folder, where the case files go; logs() holds its captured stdout and stderr, so that a run
// that must write nothing leaves work() as it was.
class Scratch {
 public:
  Scratch() : root_("partimix_app") {
    fs::create_directories(work());
    fs::create_directories(logs());
  }

  fs::path work() const { return root_ / "work"; }
  fs::path logs() const { return root_ / "logs"; }

  // Writes `text` to work()/name.
  void write(const std::string& name, const std::string& text) const {
    std::ofstream(work() / name, std::ios::binary) << text;
  }

  // The names in work(), sorted.
  std::vector<std::string> work_entries() const {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(work()))
      names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }

 private:
  test_support::TempDir root_;
};

struct Outcome {
  int exit_code = -1;  // the exit status, or 128 + the signal number when a signal ended it
  std::string out;
  std::string err;
};

// partimix running in a child process in scratch.work(), stdout and stderr going to files in
// scratch.logs(). A child still running when the object goes is killed.
class Child {
 public:
  // file_size_limit > 0: no file may grow past that many bytes (RLIMIT_FSIZE, with SIGXFSZ
  // ignored), so that a write fails as on a full disk.
  Child(const Scratch& scratch, const std::vector<std::string>& arguments,
        rlim_t file_size_limit = 0)
      : out_file_(scratch.logs() / "stdout.txt"), err_file_(scratch.logs() / "stderr.txt") {
    std::vector<std::string> words{PARTIMIX_BINARY};
    words.insert(words.end(), arguments.begin(), arguments.end());
    std::vector<char*> argv;
    for (auto& word : words)
      argv.push_back(word.data());
    argv.push_back(nullptr);
    const std::string work = scratch.work().string();
    const std::string out = out_file_.string();
    const std::string err = err_file_.string();
    pid_ = ::fork();
    if (pid_ == 0)
      exec_in_child(work.c_str(), out.c_str(), err.c_str(), argv.data(), file_size_limit);
    if (pid_ < 0)
      ADD_FAILURE() << "fork failed: errno " << errno;
  }
  ~Child() {
    if (pid_ > 0) {
      ::kill(pid_, SIGKILL);
      ::waitpid(pid_, nullptr, 0);
    }
  }
  Child(const Child&) = delete;
  Child& operator=(const Child&) = delete;

  void signal(int number) const { ::kill(pid_, number); }

  // Waits for the program to end; past kTimeLimit it is killed and the test fails.
  Outcome wait() {
    Outcome outcome;
    if (pid_ <= 0)
      return outcome;
    const auto deadline = Clock::now() + kTimeLimit;
    int status = 0;
    while (::waitpid(pid_, &status, WNOHANG) == 0) {
      if (Clock::now() > deadline) {
        ADD_FAILURE() << "partimix did not end within " << kTimeLimit.count() << " s; killed";
        ::kill(pid_, SIGKILL);
        ::waitpid(pid_, &status, 0);
        break;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    pid_ = -1;
    outcome.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    outcome.out = read_file(out_file_);
    outcome.err = read_file(err_file_);
    return outcome;
  }

 private:
  // Only async-signal-safe calls between fork and exec.
  [[noreturn]] static void exec_in_child(const char* work, const char* out, const char* err,
                                         char* const* argv, rlim_t file_size_limit) {
    const int out_fd = ::open(out, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int err_fd = ::open(err, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (file_size_limit > 0) {
      const rlimit limit{file_size_limit, file_size_limit};
      ::signal(SIGXFSZ, SIG_IGN);
      ::setrlimit(RLIMIT_FSIZE, &limit);
    }
    if (::chdir(work) == 0 && out_fd >= 0 && err_fd >= 0 && ::dup2(out_fd, STDOUT_FILENO) >= 0 &&
        ::dup2(err_fd, STDERR_FILENO) >= 0) {
      ::execv(argv[0], argv);
    }
    ::_exit(127);
  }

  fs::path out_file_;
  fs::path err_file_;
  pid_t pid_ = -1;
};

// Runs partimix with `arguments` in scratch.work() and waits for it.
inline Outcome run_partimix(const Scratch& scratch, const std::vector<std::string>& arguments) {
  return Child(scratch, arguments).wait();
}

// Waits until `file` exists; false after kTimeLimit.
inline bool wait_for_file(const fs::path& file) {
  const auto deadline = Clock::now() + kTimeLimit;
  while (!fs::exists(file)) {
    if (Clock::now() > deadline)
      return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return true;
}

struct Series {
  std::string header;
  std::vector<std::vector<double>> rows;
};

inline Series read_series(const fs::path& file) {
  Series series;
  std::ifstream in(file);
  std::getline(in, series.header);
  for (std::string line; std::getline(in, line);) {
    std::vector<double> row;
    std::istringstream cells(line);
    for (std::string cell; std::getline(cells, cell, ',');)
      row.push_back(std::stod(cell));
    series.rows.push_back(row);
  }
  return series;
}

struct FrameEntry {
  double time = 0.0;
  std::string file;  // relative to the .pvd's folder
};

// The DataSet entries of a .pvd collection, in file order.
inline std::vector<FrameEntry> read_pvd(const fs::path& file) {
  static const std::regex data_set(R"re(<DataSet timestep="([^"]*)"[^>]*file="([^"]*)")re");
  const std::string text = read_file(file);
  std::vector<FrameEntry> entries;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), data_set);
       it != std::sregex_iterator(); ++it) {
    entries.push_back({std::stod((*it)[1].str()), (*it)[2].str()});
  }
  return entries;
}

// The names of the files in out/frames, sorted.
inline std::vector<std::string> frame_files(const fs::path& out) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(out / "frames"))
    names.push_back("frames/" + entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

inline std::vector<std::string> files_of(const std::vector<FrameEntry>& entries) {
  std::vector<std::string> files;
  for (const auto& entry : entries)
    files.push_back(entry.file);
  return files;
}

inline nlohmann::json read_json(const fs::path& file) {
  return nlohmann::json::parse(read_file(file));
}

}  // namespace partimix::cli_test
