#pragma once
// Progress of a run on the console: simulated time, percent done, estimated time left and
// throughput in particle-steps per second, e.g.
//   t = 0.1234 s  12.3%  ETA 00:01:23  4.56e+06 particle-steps/s
// On a terminal (live) one line is redrawn in place at most five times a second; otherwise (a
// log file, a batch job) a plain line is printed at most every plain_interval seconds.
#include <cstddef>
#include <cstdio>
#include <functional>
#include <string>

namespace partimix {

class Progress {
 public:
  // Seconds on a monotonic clock. Injectable so that tests need not sleep.
  using Clock = std::function<double()>;

  static constexpr double kLiveInterval = 0.2;  // [s] between redraws of the live line

  // live: the stream is a terminal (the caller passes isatty(fileno(stream))). An empty clock
  // means the steady clock; the run's wall time starts at construction.
  Progress(double end_time, std::FILE* stream, bool live, double plain_interval = 5.0,
           Clock clock = {});

  // The run has reached simulated time `time` after `steps` steps in all, with `particles`
  // particles now. Prints if the interval since the last print has passed.
  void update(double time, std::size_t steps, std::size_t particles);

  // Prints the latest state if it was not printed yet and ends the live line with a newline.
  // Call it at the end of a run, also of a failed one; later calls do nothing.
  void finish();

 private:
  std::string line(double now) const;
  void print(double now);

  double end_time_;
  std::FILE* stream_;
  bool live_;
  double interval_;
  Clock clock_;
  double start_;
  double last_print_;
  double time_ = 0.0;
  std::size_t steps_ = 0;
  double particle_steps_ = 0.0;
  bool pending_ = false;
  std::size_t drawn_width_ = 0;
  bool finished_ = false;
};

}  // namespace partimix
