#pragma once
// Building and running a case in this process, for tests that need the run's summary and its
// figures (the analyses' time averages and final values): from a case file's text, into a
// folder of the test's or a temporary one, fresh or from a checkpoint.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include "app/runner.hpp"
#include "app/simulation.hpp"
#include "core/error.hpp"
#include "core/state_archive.hpp"
#include "io/case.hpp"
#include "io/checkpoint_folder.hpp"
#include "io/run_metadata.hpp"
#include "support/temp_dir.hpp"

namespace partimix::test_support {

struct CaseRun {
  io::RunSummary summary;
  std::map<std::string, double> figures;
};

// Writes `text` to `dir`/case.yaml and loads it.
inline io::Case load_case_text(const TempDir& dir, const std::string& text) {
  std::ofstream(dir / "case.yaml") << text;
  return io::load_case((dir / "case.yaml").string());
}

// The key an InputError names when the case `text` is loaded, or "no error".
inline std::string key_of_load_error(const std::string& text) {
  const TempDir dir;
  try {
    load_case_text(dir, text);
  } catch (const InputError& error) {
    return error.location().key_path;
  }
  return "no error";
}

// Runs `simulation` (built from `the_case`) with its outputs in `out`, from `checkpoint` when
// one is given (the simulation then built with for_restore).
inline CaseRun run_simulation(const io::Case& the_case, app::Simulation& simulation,
                              const std::filesystem::path& out,
                              const StateArchive* checkpoint = nullptr) {
  app::RunOptions options;
  options.output_dir = out;
  options.show_progress = false;
  app::Runner runner(the_case, simulation, options);
  CaseRun run;
  run.summary = runner.run(checkpoint);
  run.figures = runner.figures();
  return run;
}

// Builds `the_case` (for a restore when `checkpoint` is given) and runs it into `out`.
inline CaseRun run_case_into(const io::Case& the_case, const std::filesystem::path& out,
                             const StateArchive* checkpoint = nullptr) {
  app::Simulation simulation = app::build_simulation(the_case, {checkpoint != nullptr});
  return run_simulation(the_case, simulation, out, checkpoint);
}

// The case `whole` (a case file's text) run through into dir/whole; and into dir/parts, the case
// `half` (the same, ending sooner) and then `whole` again from half's newest checkpoint. The
// caller compares the two folders.
inline void run_through_and_resumed(const TempDir& dir, const std::string& whole,
                                    const std::string& half) {
  const io::Case through = load_case_text(dir, whole);
  ASSERT_EQ(run_case_into(through, dir / "whole").summary.status, "completed");
  ASSERT_EQ(run_case_into(load_case_text(dir, half), dir / "parts").summary.status, "completed");
  const StateArchive checkpoint = io::CheckpointFolder(dir / "parts" / "checkpoints").read_latest();
  ASSERT_EQ(run_case_into(through, dir / "parts", &checkpoint).summary.status, "completed");
}

inline CaseRun run_case(const io::Case& the_case) {
  app::Simulation simulation = app::build_simulation(the_case);
  const TempDir out("case_run");
  return run_simulation(the_case, simulation, out.path());
}

}  // namespace partimix::test_support
