// An analysis on a schedule of its own (analyses[i].sample_interval, sample_from, sample_until;
// issue 15: a 40 us impact after a 1 s fall needed a 79 MB series.csv): its rows go to
// series_<name>.csv at the first step at or past each sample_from + j sample_interval up to
// sample_until (plus one at the end when the span reaches it), and series.csv no longer holds
// its columns.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "cli_support.hpp"

namespace partimix::cli_test {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

const std::string kFallingWater = R"(name: falling_water
solver: sph
dimensions: 2
gravity: [0, -9.81]
domain: {min: [-0.1, -0.1], max: [0.5, 0.4]}
time: {end: 0.05, output_interval: 0.05, sample_interval: 0.01}
sph: {spacing: 0.02}
fluid:
  density: 1000
  viscosity: 1.0e-3
  regions: [{shape: box, min: [0, 0], max: [0.1, 0.2]}]
walls: [{shape: box, min: [0, 0], max: [0.4, 0.3], open: [y+]}]
analyses:
  - {type: front_position, axis: x, name: front, sample_interval: 0.001, sample_from: 0.02,
     sample_until: 0.03}
)";

TEST(AnalysisSchedule, RowsGoToTheirOwnFileOnTheirOwnTimes) {
  const Scratch scratch;
  scratch.write("case.yaml", kFallingWater);
  const Outcome outcome = run_partimix(scratch, {"run", "case.yaml", "--out", "out", "-q"});
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  const Series main = read_series(scratch.work() / "out" / "series.csv");
  EXPECT_THAT(main.header, Not(HasSubstr("front")));
  const Series own = read_series(scratch.work() / "out" / "series_front.csv");
  EXPECT_EQ(own.header, "time [s],step [-],dt [s],front.front_x [m]");
  ASSERT_GE(own.rows.size(), 11u);
  // A row at the first step at or past each multiple (steps of about 2e-4 s), none outside.
  for (std::size_t j = 0; j < own.rows.size(); ++j) {
    const double t = own.rows[j][0];
    EXPECT_GE(t, 0.02 - 1e-12);
    EXPECT_LE(t, 0.03 + 5e-4);
    EXPECT_NEAR(t, 0.02 + 0.001 * static_cast<double>(j), 5e-4) << j;
  }
  EXPECT_EQ(own.rows.size(), 11u);
}

}  // namespace
}  // namespace partimix::cli_test
