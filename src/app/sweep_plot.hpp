#pragma once
// The Np-Re plot of a sweep (docs/sweeps.md), drawn by tools/plot_sweep.py.
#include <filesystem>

#include "app/sweep_table.hpp"

namespace partimix::app {

// True when at least two rows have positive figures Re and Np.
bool can_plot_np_re(const SweepTable& table);

// Runs tools/plot_sweep.py on the sweep folder: DIR/np_re.png, and the fitted slope on stdout.
// Returns the script's exit code (1 when it cannot be started).
int plot_np_re(const std::filesystem::path& sweep_dir);

}  // namespace partimix::app
