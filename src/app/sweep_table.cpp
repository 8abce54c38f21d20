#include "app/sweep_table.hpp"

#include <algorithm>
#include <ostream>
#include <set>

#include <fmt/format.h>

#include "io/atomic_file.hpp"

namespace partimix::app {
namespace {

// The unit of figure `name` as the runs report it ([-] for none or when none says).
std::string unit_of(const SweepTable& table, const std::string& name) {
  for (const SweepRow& row : table.rows) {
    const auto found = row.record.units.find(name);
    if (found != row.record.units.end() && !found->second.empty())
      return found->second;
  }
  return "-";
}

std::vector<std::string> header(const SweepTable& table, const std::vector<std::string>& names) {
  std::vector<std::string> cells{"run"};
  cells.insert(cells.end(), table.keys.begin(), table.keys.end());
  cells.push_back("status");
  for (const std::string& name : names)
    cells.push_back(fmt::format("{} [{}]", name, unit_of(table, name)));
  cells.push_back("unreliable");
  return cells;
}

std::vector<std::string> row_cells(const SweepRow& row, const std::vector<std::string>& names,
                                   const std::string& number_format) {
  std::vector<std::string> cells{row.run};
  cells.insert(cells.end(), row.values.begin(), row.values.end());
  cells.push_back(row.record.status);
  for (const std::string& name : names) {
    const auto found = row.record.figures.find(name);
    cells.push_back(found == row.record.figures.end()
                        ? std::string()
                        : fmt::format(fmt::runtime(number_format), found->second));
  }
  std::string unreliable;
  for (const std::string& name : names) {
    if (row.record.caveats.contains(name))
      unreliable += (unreliable.empty() ? "" : " ") + name;
  }
  cells.push_back(unreliable);
  return cells;
}

std::string csv_cell(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos)
    return text;
  std::string quoted = "\"";
  for (const char c : text) {
    if (c == '"')
      quoted.push_back('"');
    quoted.push_back(c);
  }
  quoted.push_back('"');
  return quoted;
}

std::string csv_line(const std::vector<std::string>& cells) {
  std::string line;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    if (i > 0)
      line.push_back(',');
    line.append(csv_cell(cells[i]));
  }
  line.push_back('\n');
  return line;
}

std::vector<std::size_t> column_widths(const std::vector<std::vector<std::string>>& cells) {
  std::vector<std::size_t> widths(cells.front().size(), 0);
  for (const auto& line : cells) {
    for (std::size_t i = 0; i < line.size(); ++i)
      widths[i] = std::max(widths[i], line[i].size());
  }
  return widths;
}

}  // namespace

std::vector<std::string> figure_names(const SweepTable& table) {
  std::set<std::string> names;
  for (const SweepRow& row : table.rows) {
    for (const auto& [name, value] : row.record.figures)
      names.insert(name);
  }
  return {names.begin(), names.end()};
}

std::vector<std::vector<std::string>> table_cells(const SweepTable& table,
                                                  const std::string& number_format) {
  const std::vector<std::string> names = figure_names(table);
  std::vector<std::vector<std::string>> cells{header(table, names)};
  for (const SweepRow& row : table.rows)
    cells.push_back(row_cells(row, names, number_format));
  return cells;
}

void write_sweep_csv(const std::filesystem::path& file, const SweepTable& table) {
  const std::vector<std::vector<std::string>> cells = table_cells(table, "{}");
  io::write_atomically(file, [&](std::ostream& out) {
    for (const auto& line : cells)
      out << csv_line(line);
  });
}

void print_sweep_table(std::FILE* stream, const SweepTable& table) {
  const std::vector<std::vector<std::string>> cells = table_cells(table, "{:.4g}");
  const std::vector<std::size_t> widths = column_widths(cells);
  for (const auto& line : cells) {
    std::string text;
    for (std::size_t i = 0; i < line.size(); ++i)
      text += fmt::format("{:<{}}", line[i], i + 1 < line.size() ? widths[i] + 2 : 0);
    fmt::print(stream, "{}\n", text);
  }
}

}  // namespace partimix::app
