// Height profile (docs/mixing.md, "Height profile"): a deposit built by hand along x in [0, 1],
// four bins of 0.25, heights along y. Bin 0 holds grains up to y = 0.35, bin 1 up to 0.25 (one
// on the edge x = 0.25 belongs to it), bin 2 only a wall particle (empty: NaN), bin 3 a grain at
// x = 1 (the end belongs to the last bin) at 0.05 and fluid at 0.02. Grains beyond the span do
// not count. So the heights are 0.35, 0.25, NaN, 0.05, height_max = 0.35 and runout = 1 (the
// upper edge of bin 3); without the particles of bin 3, runout = 0.5. Exact values: the heights
// are particle coordinates, the edges round-off (1e-12).
#include "analysis/height_profile.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "load_fixtures.hpp"

namespace partimix::analysis {
namespace {

using analysis_test::add_particle;
using analysis_test::sample_once;

constexpr double kTight = 1e-12;

HeightLine line(int axis, int vertical, double from, double to, int bins) {
  HeightLine l;
  l.axis = axis;
  l.vertical = vertical;
  l.from = from;
  l.to = to;
  l.bins = bins;
  return l;
}

const HeightLine kAlongX = line(0, 1, 0.0, 1.0, 4);

// The deposit of the header; with `toe` false, the particles of bin 3 lie beyond the span.
void add_deposit(ParticleStore& store, bool toe) {
  for (const double y : {0.05, 0.15, 0.25, 0.35})
    add_particle(store, ParticleKind::grain, Vec3(0.1, y, 0.0));
  add_particle(store, ParticleKind::grain, Vec3(0.0, 0.3, 0.0));
  add_particle(store, ParticleKind::grain, Vec3(0.3, 0.2, 0.0));
  add_particle(store, ParticleKind::grain, Vec3(0.45, 0.25, 0.0));
  add_particle(store, ParticleKind::grain, Vec3(0.25, 0.1, 0.0));
  add_particle(store, ParticleKind::wall, Vec3(0.6, 2.0, 0.0));
  add_particle(store, ParticleKind::grain, Vec3(toe ? 1.0 : 2.0, 0.05, 0.0));
  add_particle(store, ParticleKind::fluid, Vec3(toe ? 0.8 : 2.0, 0.02, 0.0));
  add_particle(store, ParticleKind::grain, Vec3(-0.01, 5.0, 0.0));
  add_particle(store, ParticleKind::grain, Vec3(1.01, 5.0, 0.0));
}

// One sample of `profile` over the deposit.
std::vector<double> sample_deposit(Analysis& profile, bool toe, double time) {
  ParticleStore store;
  add_deposit(store, toe);
  return sample_once(profile, store, time);
}

TEST(HeightProfile, ColumnsPerBin) {
  const HeightProfile profile(kAlongX);
  const std::vector<Column> columns = profile.columns();
  ASSERT_EQ(columns.size(), 4u);
  EXPECT_EQ(columns[0].name, "height_0");
  EXPECT_EQ(columns[3].name, "height_3");
  EXPECT_EQ(columns[2].unit, "m");
}

TEST(HeightProfile, TopOfEachBinAndNaNWhenEmpty) {
  HeightProfile profile(kAlongX);
  const std::vector<double> values = sample_deposit(profile, true, 0.0);
  EXPECT_EQ(values[0], 0.35);
  EXPECT_EQ(values[1], 0.25);
  EXPECT_TRUE(std::isnan(values[2]));
  EXPECT_EQ(values[3], 0.05);
  Figures figures;
  profile.add_figures(figures);
  ASSERT_EQ(figures.size(), 2u);
  EXPECT_EQ(figures.at("height_max"), 0.35);
  EXPECT_EQ(figures.unit("height_max"), "m");
  EXPECT_NEAR(figures.at("runout"), 1.0, kTight);
  EXPECT_EQ(figures.unit("runout"), "m");
}

TEST(HeightProfile, FiguresAreOfTheLastSample) {
  HeightProfile profile(kAlongX);
  sample_deposit(profile, true, 0.0);
  const std::vector<double> values = sample_deposit(profile, false, 1.0);
  EXPECT_TRUE(std::isnan(values[3]));
  Figures figures;
  profile.add_figures(figures);
  EXPECT_EQ(figures.at("height_max"), 0.35);
  EXPECT_NEAR(figures.at("runout"), 0.5, kTight);
}

TEST(HeightProfile, AnyAxesAndHeightsBelowZero) {
  // Along z in [-1, 1] (two bins), heights along y, whatever x: bin 0 holds y = 0.3 and 0.7,
  // bin 1 only y = -0.4 and -0.1, so the heights are 0.7 and -0.1.
  ParticleStore store;
  add_particle(store, ParticleKind::grain, Vec3(5.0, 0.3, -0.5));
  add_particle(store, ParticleKind::grain, Vec3(-7.0, 0.7, -0.2));
  add_particle(store, ParticleKind::grain, Vec3(0.0, -0.4, 0.5));
  add_particle(store, ParticleKind::grain, Vec3(3.0, -0.1, 0.9));
  HeightProfile profile(line(2, 1, -1.0, 1.0, 2));
  const std::vector<double> values = sample_once(profile, store, 0.0);
  EXPECT_EQ(values[0], 0.7);
  EXPECT_EQ(values[1], -0.1);
  Figures figures;
  profile.add_figures(figures);
  EXPECT_EQ(figures.at("height_max"), 0.7);
  EXPECT_NEAR(figures.at("runout"), 1.0, kTight);
}

TEST(HeightProfile, NoMaterialInTheSpanNoFigures) {
  HeightProfile profile(kAlongX);
  Figures figures;
  profile.add_figures(figures);
  EXPECT_TRUE(figures.empty());
  ParticleStore store;
  add_particle(store, ParticleKind::grain, Vec3(3.0, 1.0, 0.0));
  sample_once(profile, store, 0.0);
  profile.add_figures(figures);
  EXPECT_TRUE(figures.empty());
}

TEST(HeightProfile, ReplayGivesTheSameFigures) {
  HeightProfile original(kAlongX);
  const std::vector<double> first = sample_deposit(original, true, 0.0);
  const std::vector<double> last = sample_deposit(original, false, 1.0);
  Figures expected;
  original.add_figures(expected);
  HeightProfile replayed(kAlongX);
  replayed.replay(0.0, first);
  replayed.replay(1.0, last);
  Figures figures;
  replayed.add_figures(figures);
  EXPECT_EQ(figures.values(), expected.values());
}

TEST(HeightProfile, BadLinesAreRefused) {
  EXPECT_THROW(HeightProfile(line(0, 0, 0.0, 1.0, 4)), std::invalid_argument);
  EXPECT_THROW(HeightProfile(line(3, 1, 0.0, 1.0, 4)), std::invalid_argument);
  EXPECT_THROW(HeightProfile(line(0, -1, 0.0, 1.0, 4)), std::invalid_argument);
  EXPECT_THROW(HeightProfile(line(0, 1, 1.0, 1.0, 4)), std::invalid_argument);
  EXPECT_THROW(HeightProfile(line(0, 1, 0.0, 1.0, 0)), std::invalid_argument);
}

TEST(HeightProfile, RegisteredByName) {
  AnalysisOptions options;
  options.height = kAlongX;
  const auto analysis = analysis_registry().create("height_profile", options);
  ASSERT_NE(analysis, nullptr);
  EXPECT_EQ(sample_deposit(*analysis, true, 0.0)[0], 0.35);
}

}  // namespace
}  // namespace partimix::analysis
