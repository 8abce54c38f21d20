#pragma once
// The results table of a sweep (docs/sweeps.md): one row per run with its folder name, the
// varied values, the status and the summary figures; written as DIR/sweep.csv and printed.
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "app/run_record.hpp"

namespace partimix::app {

struct SweepRow {
  std::string run;                  // folder name inside the sweep folder
  std::vector<std::string> values;  // one per varied key
  RunRecord record;
};

struct SweepTable {
  std::vector<std::string> keys;  // the varied key paths
  std::vector<SweepRow> rows;
};

// The names of every figure of any row, sorted.
std::vector<std::string> figure_names(const SweepTable& table);

// Header and rows as text: run, the keys, status, then figure_names(); a figure a run lacks is
// an empty cell. Numbers are written with fmt's `number_format` (e.g. "{}", "{:.4g}").
std::vector<std::vector<std::string>> table_cells(const SweepTable& table,
                                                  const std::string& number_format);

// Writes the table as CSV with numbers at full precision, atomically. Cells holding a comma,
// a quote or a line break are quoted. Throws RunError naming the file on an I/O failure.
void write_sweep_csv(const std::filesystem::path& file, const SweepTable& table);

// Prints the table with aligned columns and 4 significant digits.
void print_sweep_table(std::FILE* stream, const SweepTable& table);

}  // namespace partimix::app
