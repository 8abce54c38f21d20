#pragma once
// run.json: what a run was and how it went (DESIGN.md, "Inputs, outputs, errors"). The caller
// composes {"version": ..., "case": resolved case, "run": to_json(summary)}.
#include <cstddef>
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

namespace partimix::io {

struct RunSummary {
  std::string status;   // e.g. "completed", "failed", "interrupted"
  std::string message;  // why it failed; empty on success
  std::size_t particles = 0;
  std::size_t steps = 0;
  double simulated_time = 0.0;  // [s]
  double wall_seconds = 0.0;    // [s]
  int threads = 0;
  // This process's share: a resumed run's steps and wall_seconds count the processes before it
  // too, which may have run on other thread counts.
  std::size_t process_steps = 0;
  double process_wall_seconds = 0.0;  // [s]
};

// The summary's members under their own names, plus particle_steps_per_second =
// particles * steps / wall_seconds and process_particle_steps_per_second from this process's
// share (each 0 when its wall time is 0).
nlohmann::json to_json(const RunSummary& summary);

// Writes content as indented JSON to "<file>.tmp" and renames it to file. Throws RunError
// naming the file on any I/O failure.
void write_run_json(const std::filesystem::path& file, const nlohmann::json& content);

}  // namespace partimix::io
