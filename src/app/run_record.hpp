#pragma once
// What one run of a sweep reports, read back from the run.json in its output folder
// (docs/sweeps.md): its status and its summary figures.
#include <filesystem>
#include <map>
#include <string>

namespace partimix::app {

struct RunRecord {
  std::string status;                          // run.json "run"."status", or "failed"
  std::map<std::string, double> figures;       // run.json "figures": name -> number
  std::map<std::string, std::string> caveats;  // run.json "caveats": figure -> why unreliable
  std::map<std::string, std::string> units;    // run.json "figure_units": figure -> unit
};

// The record of the run that wrote `run_dir`. The status is "failed" when run.json is missing
// or unreadable, or still says "running" (the run ended without finishing). Figures that are
// not numbers are left out; a run.json without "figures" gives none.
RunRecord read_run_record(const std::filesystem::path& run_dir);

}  // namespace partimix::app
