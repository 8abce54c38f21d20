// `partimix run` end to end with the analyses body_loads, power_number and mixing and a tracer
// (docs/power.md, docs/mixing.md): a 2D box of fluid stirred by a solid plate turning at
// 300 rpm. series.csv has the columns and rows that follow from the set-up, run.json the
// figures over the last half revolution (average_revolutions 0.5), and the frames the tracer tag.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <regex>
#include <string>
#include <vector>

#include "cli_support.hpp"

namespace partimix::cli_test {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

// The box [0, 0.2]^2 full of fluid (rho 1000, mu 1 Pa s) at spacing 0.01, lattice points at
// 0.005 + 0.01 i; walls[1] is the plate [0.058, 0.142] x [0.088, 0.112] (d = 0.084 m) turning
// about its centre (0.1, 0.1) at 300 rpm (N = 5 r/s, period 0.2 s) after a 0.05 s ramp. Its
// particles lie on its own lattice, 0.063 + 0.01 i by 0.093 and 0.103, 0.002 off the fluid's
// (docs/geometry-meshes.md, "Solid walls"): the fluid points inside it are cleared (x 0.065 to
// 0.135 by y 0.095 and 0.105: 16) and those closer than a spacing to one of its particles (x
// 0.055 by the same two rows, 0.0082 m from the nearest; x 0.065 to 0.135 at y 0.085, 0.0082 m;
// 10), so 400 - 26 = 374 fluid particles; the rows and columns on the far sides, 0.012 m from the
// nearest plate particle, stay. The tracer is the fluid at y < 0.1: 200 - 17 = 183 particles,
// 191 above.
const std::string kStirredBox = R"(name: stirred_box
solver: sph
dimensions: 2
domain:
  min: [-0.05, -0.05]
  max: [0.25, 0.25]
time:
  end: 0.2
  output_interval: 0.1
  sample_interval: 0.01
sph:
  spacing: 0.01
  max_velocity: 1.5
fluid:
  density: 1000
  viscosity: 1.0
  tracer: {point: [0.1, 0.1]}
  regions:
    - {shape: box, min: [0, 0], max: [0.2, 0.2]}
walls:
  - {shape: box, min: [0, 0], max: [0.2, 0.2]}
  - shape: plate
    centre: [0.1, 0.1]
    length: 0.084
    width: 0.024
    solid: true
    motion: {type: rotation, axis_point: [0.1, 0.1], rpm: 300, ramp_time: 0.05}
analyses:
  - {type: body_loads, body: 1, vessel_axis_point: [0.1, 0.1], average_revolutions: 0.5}
  - {type: power_number, body: 1, diameter: 0.084, average_revolutions: 0.5}
  - {type: mixing, axis_point: [0.1, 0.1], radius: 0.085, cells: [1, 2]}
)";

constexpr double kEnd = 0.2;
// Re = rho N d^2 / mu = 1000 5 0.084^2 / 1 = 1000 5 0.007056 = 35.28.
constexpr double kReynolds = 35.28;
// rho N^3 d^5 = 1000 125 0.084^5 = 125000 4.18211942e-6 = 0.522764928 W: Np = P / this.
constexpr double kPowerScale = 0.522764928;

enum Col : std::size_t {
  kTime = 0,
  kTorqueOwn = 8,
  kTorqueVessel = 9,
  kPower = 10,
  kPowerRotation = 11,
  kRe = 12,
  kNp = 13,
  kNpTotal = 14,
  kXi = 15,
  kLacey = 16,
};

class MixingRun : public ::testing::Test {
 protected:
  void SetUp() override {
    scratch_.write("case.yaml", kStirredBox);
    const Outcome outcome =
        run_partimix(scratch_, {"run", "case.yaml", "--out", "out", "-q", "-t", "1"});
    ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
    outcome_err_ = outcome.err;
  }

  fs::path out() const { return scratch_.work() / "out"; }

  Scratch scratch_;
  std::string outcome_err_;
};

void expect_relative(double actual, double expected, double tolerance, const std::string& what) {
  EXPECT_NEAR(actual, expected, tolerance * std::max(1.0, std::abs(expected))) << what;
}

TEST_F(MixingRun, SeriesHasTheLoadPowerAndMixingColumns) {
  const Series series = read_series(out() / "series.csv");
  EXPECT_EQ(series.header,
            "time [s],step [-],dt [s],kinetic_energy [J],max_speed [m/s],"
            "body1_force_x [N],body1_force_y [N],body1_force_z [N],body1_torque_own [N m],"
            "body1_torque_vessel [N m],body1_power [W],body1_power_rotation [W],"
            "Re [-],Np [-],Np_total [-],xi [-],lacey [-]");
  ASSERT_GE(series.rows.size(), 20u);
  EXPECT_NEAR(series.rows.back()[kTime], kEnd, 1e-9);
  for (std::size_t i = 0; i < series.rows.size(); ++i) {
    const std::vector<double>& row = series.rows[i];
    ASSERT_EQ(row.size(), 17u) << "row " << i;
    const std::string at = "row " + std::to_string(i);
    expect_relative(row[kRe], kReynolds, 1e-9, at);
    // The vessel axis point is the plate's own axis: the two torques are one.
    expect_relative(row[kTorqueVessel], row[kTorqueOwn], 1e-9, at);
    // Np and Np_total are the body's rotation and total power over rho N^3 d^5 (the series
    // keeps 10 significant digits).
    expect_relative(row[kNp], row[kPowerRotation] / kPowerScale, 1e-8, at);
    expect_relative(row[kNpTotal], row[kPower] / kPowerScale, 1e-8, at);
    EXPECT_GE(row[kXi], 0.0) << at;
    EXPECT_LE(row[kXi], 0.5) << at;
  }
}

TEST_F(MixingRun, FirstRowIsTheSegregatedStartAtRest) {
  // At t = 0 the ramp has the plate at rest: omega = 0, no rotation power. The disc of radius
  // 0.085 about (0.1, 0.1) holds 54 lattice points a quadrant ((a + 1/2)^2 + (b + 1/2)^2 <=
  // 72.25 for b = 0..7: 8, 8, 8, 8, 7, 6, 5, 4), 108 a half, every cleared point among them:
  // 91 fluid in the lower half (all the tracers), 99 in the upper. xi = 1/n = 0.5 (all tracers
  // in one of n = 2 cells); Lacey with the pure cells phi = 1, 0 (S^2 = 1/2), p = 91/190 and
  // nbar = 95: M = (S0^2 - 1/2) / (S0^2 (1 - 1/95)), S0^2 = p (1 - p).
  const Series series = read_series(out() / "series.csv");
  ASSERT_FALSE(series.rows.empty());
  const std::vector<double>& first = series.rows.front();
  EXPECT_EQ(first[kTime], 0.0);
  EXPECT_EQ(first[kPowerRotation], 0.0);
  EXPECT_EQ(first[kNp], 0.0);
  EXPECT_NEAR(first[kXi], 0.5, 1e-12);
  const double p = 91.0 / 190.0;
  const double s0 = p * (1.0 - p);
  EXPECT_NEAR(first[kLacey], (s0 - 0.5) / (s0 * (1.0 - 1.0 / 95.0)), 1e-9);
}

TEST_F(MixingRun, FiguresAreMeansOverTheLastHalfRevolution) {
  const nlohmann::json figures = read_json(out() / "run.json").at("figures");
  const Series series = read_series(out() / "series.csv");
  ASSERT_FALSE(series.rows.empty());
  expect_relative(figures.at("Re").get<double>(), kReynolds, 1e-9, "Re");
  // Half a revolution of 60/300 = 0.2 s before the end at 0.2 s, for both analyses.
  for (const std::string& prefix : {std::string(), std::string("body1_")}) {
    EXPECT_NEAR(figures.at(prefix + "average_from").get<double>(), 0.1, 1e-9) << prefix;
    EXPECT_NEAR(figures.at(prefix + "average_to").get<double>(), kEnd, 1e-9) << prefix;
    EXPECT_NEAR(figures.at(prefix + "average_revolutions").get<double>(), 0.5, 1e-9) << prefix;
  }
  // A mean lies within the values it averages; the fluid resists the counter-clockwise turn.
  double low = std::numeric_limits<double>::infinity();
  double high = -low;
  for (const auto& row : series.rows) {
    if (row[kTime] >= 0.1 - 0.01) {
      low = std::min(low, row[kNp]);
      high = std::max(high, row[kNp]);
    }
  }
  const double np = figures.at("Np").get<double>();
  EXPECT_GT(np, 0.0);
  EXPECT_GE(np, low);
  EXPECT_LE(np, high);
  EXPECT_LT(figures.at("body1_torque_own").get<double>(), 0.0);
  EXPECT_GT(figures.at("body1_power_rotation").get<double>(), 0.0);
  // The mixing figures are the last sample's values.
  expect_relative(figures.at("xi_final").get<double>(), series.rows.back()[kXi], 1e-9, "xi");
  expect_relative(figures.at("lacey_final").get<double>(), series.rows.back()[kLacey], 1e-9,
                  "lacey");
}

// The Int32 point-data array `name` of a .vtp frame: its offset into the appended block (after
// the '_' that opens it) holds a UInt64 byte count, then the values.
std::vector<std::int32_t> int32_array(const std::string& frame, const std::string& name) {
  std::smatch match;
  const std::regex array("Name=\"" + name + "\"[^>]*offset=\"([0-9]+)\"");
  if (!std::regex_search(frame, match, array)) {
    ADD_FAILURE() << "no array " << name;
    return {};
  }
  const std::size_t at =
      frame.find('_', frame.find("<AppendedData")) + 1 + std::stoul(match[1].str());
  std::uint64_t bytes = 0;
  std::memcpy(&bytes, frame.data() + at, sizeof bytes);
  std::vector<std::int32_t> values(bytes / sizeof(std::int32_t));
  std::memcpy(values.data(), frame.data() + at + sizeof bytes,
              values.size() * sizeof(std::int32_t));
  return values;
}

// The plate, 0.024 m wide, is thinner than 2h = 0.03 m: the figures of its loads say so.
TEST_F(MixingRun, FiguresOfTheLoadsOnASeeThroughPlateCarryACaveat) {
  const nlohmann::json run = read_json(out() / "run.json");
  const nlohmann::json& caveats = run.at("caveats");
  for (const char* figure : {"Np", "Re", "body1_torque_own"})
    EXPECT_THAT(caveats.at(figure).get<std::string>(), HasSubstr("walls[1] is about")) << figure;
  EXPECT_FALSE(caveats.contains("xi_final"));
  EXPECT_THAT(run.at("warnings").at(0).get<std::string>(), HasSubstr("walls[1] is about"));
}

// Every figure has its unit in run.json, and the printed summary shows it.
TEST_F(MixingRun, FiguresCarryTheirUnits) {
  const nlohmann::json units = read_json(out() / "run.json").at("figure_units");
  EXPECT_EQ(units.at("Np"), "-");
  EXPECT_EQ(units.at("body1_torque_own"), "N m");
  EXPECT_EQ(units.at("body1_power"), "W");
  EXPECT_EQ(units.at("average_from"), "s");
  EXPECT_EQ(units.size(), read_json(out() / "run.json").at("figures").size());
  EXPECT_THAT(outcome_err_, HasSubstr("body1_torque_own [N m]"));
}

// The plots are titled with the case, and the plot of a column whose mean is a figure shows the
// averaging window (and says when the figure is unreliable).
TEST_F(MixingRun, PlotsCarryTheTitleAndTheAveragingWindow) {
  const Outcome plot = run_partimix(scratch_, {"plot", "out"});
  ASSERT_EQ(plot.exit_code, 0) << plot.err;
  EXPECT_THAT(plot.out, HasSubstr("plot_series: title 'stirred_box'"));
  EXPECT_THAT(plot.out, HasSubstr("Np.png: averaging window t = 0.1 to 0.2 s, mean "));
  EXPECT_THAT(plot.out, HasSubstr("body1_torque_own.png: averaging window t = 0.1 to 0.2 s"));
  EXPECT_THAT(plot.out, HasSubstr("(unreliable)"));
  EXPECT_THAT(plot.out, Not(HasSubstr("xi.png: averaging")));
}

// A run shorter than the ramp plus the averaging window: the means take in the ramp, and the
// summary marks them (issue 15: the demo's Np included the start-up ramp without a word).
TEST(MixingRunCaveats, AnAverageThatTakesInTheRampIsMarked) {
  const Scratch scratch;
  scratch.write("case.yaml", replaced(kStirredBox, "width: 0.024", "width: 0.03"));
  const Outcome outcome = run_partimix(
      scratch, {"run", "case.yaml", "--out", "out", "-q", "-t", "1", "--set", "time.end=0.12"});
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  const nlohmann::json caveats = read_json(scratch.work() / "out" / "run.json").at("caveats");
  const std::string np = caveats.at("Np");
  EXPECT_THAT(np, HasSubstr("averaged over t = 0.02 to 0.12 s"));
  EXPECT_THAT(np, HasSubstr("takes in the start-up ramp (ramp_time 0.05 s)"));
  EXPECT_THAT(np, HasSubstr("run to at least t = 0.15 s"));
  EXPECT_THAT(outcome.err, HasSubstr("(unreliable, see below)"));
  EXPECT_THAT(outcome.err, HasSubstr("warning: Np, Np_total, Re"));
}

TEST_F(MixingRun, FramesTagHalfTheFluidAsTracer) {
  // Tags stay with the particles: 180 tracers (tag 1) and 180 others among the fluid in the
  // first and the last frame; wall particles carry tag 0.
  const std::vector<FrameEntry> frames = read_pvd(out() / "sph.pvd");
  ASSERT_GE(frames.size(), 2u);
  for (const FrameEntry& entry : {frames.front(), frames.back()}) {
    const std::string frame = read_file(out() / entry.file);
    const std::vector<std::int32_t> tag = int32_array(frame, "tag");
    const std::vector<std::int32_t> kind = int32_array(frame, "kind");
    ASSERT_EQ(tag.size(), kind.size()) << entry.file;
    int tracers = 0;
    int others = 0;
    for (std::size_t i = 0; i < tag.size(); ++i) {
      if (kind[i] != 0) {
        EXPECT_EQ(tag[i], 0) << entry.file << " wall particle " << i;
        continue;
      }
      EXPECT_TRUE(tag[i] == 0 || tag[i] == 1) << entry.file << " particle " << i;
      tracers += tag[i] == 1 ? 1 : 0;
      others += tag[i] == 0 ? 1 : 0;
    }
    EXPECT_EQ(tracers, 183) << entry.file;
    EXPECT_EQ(others, 191) << entry.file;
  }
}

}  // namespace
}  // namespace partimix::cli_test
