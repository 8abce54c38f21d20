#include "app/sweep_plot.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "app/child_process.hpp"
#include "app/tools_dir.hpp"
#include "core/error.hpp"

namespace partimix::app {
namespace {

bool positive(const RunRecord& record, const std::string& name) {
  const auto found = record.figures.find(name);
  return found != record.figures.end() && found->second > 0.0;
}

}  // namespace

bool can_plot_np_re(const SweepTable& table) {
  const auto rows = std::count_if(table.rows.begin(), table.rows.end(), [](const SweepRow& row) {
    return positive(row.record, "Re") && positive(row.record, "Np");
  });
  return rows >= 2;
}

int plot_np_re(const std::filesystem::path& sweep_dir) {
  const std::filesystem::path script = tools_dir() / "plot_sweep.py";
  try {
    return wait_process(start_process({"/usr/bin/python3", script.string(), sweep_dir.string()}));
  } catch (const RunError& error) {
    fmt::print(stderr, "error: {}\n", error.what());
    return kExitRunFailed;
  }
}

}  // namespace partimix::app
