#pragma once
// The two kinds of failure partimix reports, each with its own exit code (DESIGN.md, "Inputs,
// outputs, errors"): bad input (exit 2) and a failed run (exit 1).
#include <stdexcept>
#include <string>

namespace partimix {

inline constexpr int kExitSuccess = 0;
inline constexpr int kExitRunFailed = 1;
inline constexpr int kExitBadInput = 2;
inline constexpr int kExitInterrupted = 130;

// Where in an input a problem sits. line and column are 1-based; 0 means unknown.
struct InputLocation {
  std::string file;
  int line = 0;
  int column = 0;
  std::string key_path;
};

// Bad input: names the file, line, column and key path. Thrown before anything is written.
class InputError : public std::runtime_error {
 public:
  InputError(InputLocation location, const std::string& message);
  const InputLocation& location() const { return location_; }
  const std::string& message() const { return message_; }

 private:
  InputLocation location_;
  std::string message_;
};

// A run that cannot go on (NaN, particle lost, I/O failure).
class RunError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The user asked to stop (Ctrl-C, SIGTERM) during a phase that has nothing to keep yet (set-up);
// exit code kExitInterrupted.
class Interrupted : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace partimix
