#pragma once
// Where a run stands (DESIGN.md, "One run"): the clock, the step count and the times of the
// next sample, frame and checkpoint. With the methods' states, the analyses' sampled rows and
// the frame collections it is what a checkpoint holds (docs/architecture-notes.md,
// "Checkpoints"), and all a resumed run needs to go on as if never stopped.
#include <cstdint>

#include "core/state_archive.hpp"

namespace partimix::app {

struct RunState {
  double time = 0.0;  // [s]
  std::uint64_t steps = 0;
  double last_dt = 0.0;  // [s]
  double next_sample = 0.0;
  double next_frame = 0.0;
  double next_checkpoint = 0.0;
  double last_sample_time = -1.0;
  double last_frame_time = -1.0;
  double wall_seconds = 0.0;  // spent by the run before this process (a resumed run) [s]
};

// The first whole multiple of `interval` past `time` + `tolerance`, in one step whatever the
// ratio of the two (no loop that a tiny interval could stall): the next sample, frame or
// checkpoint time. Always later than `time`.
double next_multiple(double interval, double time, double tolerance);

// Under "run/".
void save_run_state(const RunState& state, StateArchive& archive);
RunState restore_run_state(const StateArchive& archive);

}  // namespace partimix::app
