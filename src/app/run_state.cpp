#include "app/run_state.hpp"

#include <cmath>
#include <limits>
#include <vector>

namespace partimix::app {

double next_multiple(double interval, double time, double tolerance) {
  const double after = time + tolerance;
  const double next = interval * (std::floor(after / interval) + 1.0);
  return next > after ? next : std::nextafter(after, std::numeric_limits<double>::infinity());
}
namespace {

constexpr const char* kTimes = "run/times";
constexpr const char* kSteps = "run/steps";

}  // namespace

// The times in one array, in the order of the struct.
void save_run_state(const RunState& state, StateArchive& archive) {
  archive.put_doubles(
      kTimes, std::vector<double>{state.time, state.last_dt, state.next_sample, state.next_frame,
                                  state.next_checkpoint, state.last_sample_time,
                                  state.last_frame_time, state.wall_seconds});
  archive.put_integers(kSteps, std::vector<std::int64_t>{static_cast<std::int64_t>(state.steps)});
}

RunState restore_run_state(const StateArchive& archive) {
  const auto times = archive.doubles(kTimes);
  const auto steps = archive.integers(kSteps);
  if (times.size() != 8 || steps.size() != 1 || steps[0] < 0)
    throw StateError("run/: the run's times or step count have the wrong size");
  RunState state;
  state.time = times[0];
  state.last_dt = times[1];
  state.next_sample = times[2];
  state.next_frame = times[3];
  state.next_checkpoint = times[4];
  state.last_sample_time = times[5];
  state.last_frame_time = times[6];
  state.wall_seconds = times[7];
  state.steps = static_cast<std::uint64_t>(steps[0]);
  return state;
}

}  // namespace partimix::app
