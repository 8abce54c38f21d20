// series.csv: "name [unit]" header, rows that read back to the written values, each row on
// disk as soon as it is written, and column names checked.
#include "io/series_writer.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "io/test_files.hpp"

namespace partimix::io {
namespace {

using test::read_file;
using test::TempDir;

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> result;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    result.push_back(line);
  }
  return result;
}

std::vector<double> parse_row(const std::string& line) {
  std::vector<double> values;
  std::istringstream in(line);
  for (std::string cell; std::getline(in, cell, ',');) {
    values.push_back(std::stod(cell));
  }
  return values;
}

const std::vector<SeriesColumn> kColumns = {
    {"time", "s"}, {"kinetic_energy", "J"}, {"mixing_index", ""}};

TEST(SeriesWriter, HeaderNamesColumnsWithUnits) {
  TempDir dir;
  SeriesWriter writer(dir / "series.csv", kColumns);
  EXPECT_EQ(read_file(dir / "series.csv"), "time [s],kinetic_energy [J],mixing_index [-]\n");
  EXPECT_EQ(writer.columns().size(), 3U);
}

TEST(SeriesWriter, RowsRoundTripAndAreOnDiskAtOnce) {
  TempDir dir;
  SeriesWriter writer(dir / "series.csv", kColumns);
  const std::vector<std::vector<double>> rows = {
      {0.0, 1.5e-7, 0.25}, {0.1, 123456.789, -1.0}, {1.0 / 3.0, 6.02214076e23, 1e-300}};
  for (std::size_t k = 0; k < rows.size(); ++k) {
    writer.write_row(rows[k]);
    ASSERT_EQ(lines(read_file(dir / "series.csv")).size(), k + 2) << "row not flushed";
  }
  const auto text = lines(read_file(dir / "series.csv"));
  EXPECT_EQ(text[1], "0,1.5e-07,0.25");
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const auto values = parse_row(text[k + 1]);
    ASSERT_EQ(values.size(), 3U);
    for (std::size_t c = 0; c < 3; ++c) {
      EXPECT_NEAR(values[c], rows[k][c], 5e-10 * std::abs(rows[k][c])) << k << "," << c;
    }
  }
}

TEST(SeriesWriter, RowOfWrongLengthIsRejected) {
  TempDir dir;
  SeriesWriter writer(dir / "series.csv", kColumns);
  const std::vector<double> short_row = {1.0, 2.0};
  EXPECT_THROW(writer.write_row(short_row), std::invalid_argument);
}

TEST(SeriesWriter, BadColumnNamesAreRejectedBeforeWriting) {
  TempDir dir;
  const auto file = dir / "series.csv";
  EXPECT_THROW(SeriesWriter(file, {{"time", "s"}, {"time", "s"}}), std::invalid_argument);
  EXPECT_THROW(SeriesWriter(file, {{"a,b", "s"}}), std::invalid_argument);
  EXPECT_THROW(SeriesWriter(file, {{"", "s"}}), std::invalid_argument);
  EXPECT_THROW(SeriesWriter(file, {{"power", "W,kW"}}), std::invalid_argument);
  EXPECT_FALSE(std::filesystem::exists(file));
}

TEST(SeriesWriter, UnwritableFolderThrowsRunErrorNamingFile) {
  TempDir dir;
  const auto file = dir / "missing" / "series.csv";
  try {
    SeriesWriter writer(file, kColumns);
    FAIL() << "expected RunError";
  } catch (const RunError& error) {
    EXPECT_NE(std::string(error.what()).find(file.string()), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace partimix::io
