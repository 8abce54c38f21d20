// Mass in a region (docs/mixing.md, "Mass in a region and discharge rate"). A silo of ten
// grains of 0.5 kg in the box [0, 1]^2 (2D: a flat z side) empties to 10, 8, 7, 4, 3 grains at
// t = 0, 0.5, 1, 1.5, 2 s, so M = 5, 4, 3.5, 2, 1.5 kg and the flows since the previous sample are
// 0, 2, 1, 3, 1 kg/s. The least-squares slope of M(t), with t_mean = 1 s and M_mean = 3.2 kg:
//   sum dt dM = (-1)(1.8) + (-0.5)(0.8) + 0 + (0.5)(-1.2) + (1)(-1.7) = -4.5,  sum dt^2 = 2.5,
// b = -1.8 kg/s, so the discharge rate is 1.8 kg/s; over the window [0.5, 1.5] s (M = 4, 3.5, 2):
// b = ((-0.5)(4) + (0.5)(2)) / 0.5 = -2, a rate of 2 kg/s. Tolerance 1e-12: round-off only.
#include "analysis/mass_in_region.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>
#include <vector>

#include "load_fixtures.hpp"

namespace partimix::analysis {
namespace {

using analysis_test::add_particle;
using analysis_test::sample_once;
using ::testing::HasSubstr;

constexpr double kTight = 1e-12;
constexpr double kGrainMass = 0.5;  // [kg]
constexpr std::array<double, 5> kTimes{0.0, 0.5, 1.0, 1.5, 2.0};
constexpr std::array<int, 5> kInside{10, 8, 7, 4, 3};
constexpr std::array<double, 5> kMass{5.0, 4.0, 3.5, 2.0, 1.5};
constexpr std::array<double, 5> kFlow{0.0, 2.0, 1.0, 3.0, 1.0};

MassRegion region(const Vec3& lo, const Vec3& hi) {
  MassRegion r;
  r.lo = lo;
  r.hi = hi;
  return r;
}

// The silo's box [0, 1]^2 with the fit window [fit_from, fit_until].
MassRegion box(double fit_from = 0.0, double fit_until = std::numeric_limits<double>::infinity()) {
  return {Vec3(0.0, 0.0, 0.0), Vec3(1.0, 1.0, 0.0), fit_from, fit_until};
}

// Ten grains: the first `inside` in the box (grain 0 on its face x = 0), the rest below it; and
// a wall particle of 100 kg inside, which does not count.
void add_silo(ParticleStore& store, int inside) {
  for (int j = 0; j < 10; ++j) {
    const Vec3 x =
        j == 0 ? Vec3(0.0, 0.5, 0.0) : Vec3(0.05 + 0.1 * j, j < inside ? 0.5 : -0.5, 0.0);
    store.mass()[add_particle(store, ParticleKind::grain, x)] = kGrainMass;
  }
  store.mass()[add_particle(store, ParticleKind::wall, Vec3(0.5, 0.5, 0.0))] = 100.0;
}

// One sample of `analysis` over the silo holding `inside` grains.
std::vector<double> sample_silo(Analysis& analysis, int inside, double time) {
  ParticleStore store;
  add_silo(store, inside);
  return sample_once(analysis, store, time);
}

// The values of each sample of the emptying silo.
std::vector<std::vector<double>> empty_silo(MassInRegion& analysis) {
  std::vector<std::vector<double>> rows;
  for (std::size_t k = 0; k < kTimes.size(); ++k)
    rows.push_back(sample_silo(analysis, kInside[k], kTimes[k]));
  return rows;
}

TEST(MassInRegion, Columns) {
  const MassInRegion analysis(box());
  const std::vector<Column> columns = analysis.columns();
  ASSERT_EQ(columns.size(), 2u);
  EXPECT_EQ(columns[0].name, "mass");
  EXPECT_EQ(columns[0].unit, "kg");
  EXPECT_EQ(columns[1].name, "mass_flow");
  EXPECT_EQ(columns[1].unit, "kg/s");
}

TEST(MassInRegion, CountsTheMaterialInsideTheBoxFacesIncluded) {
  // In the box [0, 1]^3: a grain of 1 kg inside, fluid of 2 kg on the face z = 1, a grain of 4 kg
  // on the corner (0, 0, 0): 7 kg. Not counted: 8 kg just beyond the face x = 1, a wall
  // particle of 16 kg inside.
  ParticleStore store;
  const std::array<std::pair<Vec3, double>, 4> material{{{Vec3(0.5, 0.5, 0.5), 1.0},
                                                         {Vec3(0.2, 0.7, 1.0), 2.0},
                                                         {Vec3(0.0, 0.0, 0.0), 4.0},
                                                         {Vec3(1.0 + 1e-12, 0.5, 0.5), 8.0}}};
  for (const auto& [x, mass] : material) {
    const ParticleKind kind = mass == 2.0 ? ParticleKind::fluid : ParticleKind::grain;
    store.mass()[add_particle(store, kind, x)] = mass;
  }
  store.mass()[add_particle(store, ParticleKind::wall, Vec3(0.5, 0.5, 0.5))] = 16.0;
  MassInRegion analysis(region(Vec3::Zero(), Vec3::Ones()));
  const std::vector<double> values = sample_once(analysis, store, 0.0);
  EXPECT_NEAR(values[0], 7.0, kTight);
  EXPECT_EQ(values[1], 0.0);  // the first sample
}

TEST(MassInRegion, MassFlowIsTheDropSinceThePreviousSample) {
  MassInRegion analysis(box());
  const std::vector<std::vector<double>> rows = empty_silo(analysis);
  for (std::size_t k = 0; k < rows.size(); ++k) {
    EXPECT_NEAR(rows[k][0], kMass[k], kTight) << k;
    EXPECT_NEAR(rows[k][1], kFlow[k], kTight) << k;
  }
  // No change: a flow of +0 (not -0 in series.csv).
  const std::vector<double> same = sample_silo(analysis, kInside.back(), 2.5);
  EXPECT_EQ(same[1], 0.0);
  EXPECT_FALSE(std::signbit(same[1]));
}

TEST(MassInRegion, DischargeRateIsMinusTheLeastSquaresSlope) {
  MassInRegion analysis(box());
  empty_silo(analysis);
  Figures figures;
  analysis.add_figures(figures);
  ASSERT_EQ(figures.size(), 2u);
  EXPECT_NEAR(figures.at("discharge_rate"), 1.8, kTight);
  EXPECT_EQ(figures.unit("discharge_rate"), "kg/s");
  EXPECT_NEAR(figures.at("mass_final"), 1.5, kTight);
  EXPECT_EQ(figures.unit("mass_final"), "kg");
  Caveats caveats;
  analysis.add_caveats(caveats);
  EXPECT_TRUE(caveats.empty());
}

TEST(MassInRegion, TheFitWindowChoosesTheSamples) {
  MassInRegion analysis(box(0.5, 1.5));
  empty_silo(analysis);
  Figures figures;
  analysis.add_figures(figures);
  EXPECT_NEAR(figures.at("discharge_rate"), 2.0, kTight);
  EXPECT_NEAR(figures.at("mass_final"), 1.5, kTight);  // the last sample, in the window or not
}

TEST(MassInRegion, TooFewSamplesInTheWindowGiveACaveatAndNoRate) {
  MassInRegion analysis(box(0.8, 1.6));  // t = 1 and 1.5 only
  empty_silo(analysis);
  Figures figures;
  analysis.add_figures(figures);
  EXPECT_FALSE(figures.contains("discharge_rate"));
  EXPECT_TRUE(figures.contains("mass_final"));
  Caveats caveats;
  analysis.add_caveats(caveats);
  ASSERT_EQ(caveats.size(), 1u);
  EXPECT_THAT(caveats.at("discharge_rate"), HasSubstr("2 sample(s)"));
  EXPECT_THAT(caveats.at("discharge_rate"), HasSubstr("needs at least 3"));
}

TEST(MassInRegion, NoSampleNoFigures) {
  const MassInRegion analysis(box());
  Figures figures;
  analysis.add_figures(figures);
  EXPECT_TRUE(figures.empty());
}

TEST(MassInRegion, ReplayRebuildsTheHistory) {
  MassInRegion original(box(0.5));
  const std::vector<std::vector<double>> rows = empty_silo(original);
  Figures expected;
  original.add_figures(expected);
  // All rows replayed: the same figures, bit for bit.
  MassInRegion replayed(box(0.5));
  for (std::size_t k = 0; k < rows.size(); ++k)
    replayed.replay(kTimes[k], rows[k]);
  Figures figures;
  replayed.add_figures(figures);
  EXPECT_EQ(figures.values(), expected.values());
  // Resumed after three rows: the next samples' flows and the figures are those of the
  // uninterrupted run.
  MassInRegion resumed(box(0.5));
  for (std::size_t k = 0; k < 3; ++k)
    resumed.replay(kTimes[k], rows[k]);
  for (std::size_t k = 3; k < rows.size(); ++k)
    EXPECT_EQ(sample_silo(resumed, kInside[k], kTimes[k]), rows[k]) << k;
  Figures resumed_figures;
  resumed.add_figures(resumed_figures);
  EXPECT_EQ(resumed_figures.values(), expected.values());
}

TEST(MassInRegion, BadRegionsAreRefused) {
  EXPECT_THROW(MassInRegion(region(Vec3(0, 0, 0), Vec3(1, 0, 0))), std::invalid_argument);
  EXPECT_THROW(MassInRegion(region(Vec3(0, 0, 1), Vec3(1, 1, 0))), std::invalid_argument);
  EXPECT_THROW(MassInRegion(box(1.0, 1.0)), std::invalid_argument);
  EXPECT_THROW(MassInRegion(box(std::nan(""), 1.0)), std::invalid_argument);
}

TEST(MassInRegion, RegisteredByName) {
  AnalysisOptions options;
  options.region_mass = box();
  const auto analysis = analysis_registry().create("mass_in_region", options);
  ASSERT_NE(analysis, nullptr);
  EXPECT_NEAR(sample_silo(*analysis, 8, 0.0)[0], 4.0, kTight);
}

}  // namespace
}  // namespace partimix::analysis
