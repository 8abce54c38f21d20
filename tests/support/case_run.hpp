#pragma once
// Building and running a case in this process into a temporary output folder, for tests that
// need the run's summary and its figures (the analyses' time averages and final values).
#include <map>
#include <string>

#include "app/runner.hpp"
#include "app/simulation.hpp"
#include "io/case.hpp"
#include "io/run_metadata.hpp"
#include "support/temp_dir.hpp"

namespace partimix::test_support {

struct CaseRun {
  io::RunSummary summary;
  std::map<std::string, double> figures;
};

inline CaseRun run_case(const io::Case& the_case) {
  app::Simulation simulation = app::build_simulation(the_case);
  const TempDir out("case_run");
  app::RunOptions options;
  options.output_dir = out.path();
  options.show_progress = false;
  app::Runner runner(the_case, simulation, options);
  CaseRun run;
  run.summary = runner.run();
  run.figures = runner.figures();
  return run;
}

}  // namespace partimix::test_support
