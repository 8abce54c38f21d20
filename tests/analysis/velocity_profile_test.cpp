// Velocity profile (docs/mixing.md, "Velocity profile"): in the simple shear v = (gamma y, 3, 0)
// sampled on a lattice symmetric about each bin's centre, the mean of v . d over a bin is exact:
// gamma y_b (d = x), 3 (d = y), (gamma y_b + 3)/sqrt 2 (d = x + y, normalised); an empty bin is
// NaN; particles beyond the segment's ends, farther than width/2 from it, or of a wall do not
// count.
#include "analysis/velocity_profile.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "load_fixtures.hpp"

namespace partimix::analysis {
namespace {

using analysis_test::add_particle;
using analysis_test::sample_once;

constexpr double kShearRate = 2.0;  // gamma [1/s]
constexpr double kTight = 1e-12;

// Fluid particles at x = 0.5 + 0.04 {-2..2}, y = 0.02 + 0.04 j (j = 0..24, so y in (0, 1)),
// z in {-0.04, 0, 0.04}, with v = (gamma y, 3, 0). Each bin of height 0.2 along y holds 5 rows
// symmetric about its centre 0.1 + 0.2 b. Decoys with v = (100, 100, 100): a wall particle on the
// line, grains at y = -0.02 and y = 1.3 on the line's prolongation, and one at z = 0.15 (farther
// than width/2 = 0.1 from the line, nearer than width).
void shear(ParticleStore& store) {
  for (int k = -1; k <= 1; ++k) {
    for (int j = 0; j < 25; ++j) {
      for (int i = -2; i <= 2; ++i) {
        const double y = 0.02 + 0.04 * j;
        const std::size_t p =
            add_particle(store, ParticleKind::fluid, Vec3(0.5 + 0.04 * i, y, 0.04 * k));
        store.velocity()[p] = Vec3(kShearRate * y, 3.0, 0.0);
      }
    }
  }
  for (const Vec3& x :
       {Vec3(0.5, 0.5, 0.0), Vec3(0.5, -0.02, 0.0), Vec3(0.5, 1.3, 0.0), Vec3(0.5, 0.5, 0.15)}) {
    const bool wall = x.y() == 0.5 && x.z() == 0.0;
    const std::size_t p = add_particle(store, wall ? ParticleKind::wall : ParticleKind::grain, x);
    store.velocity()[p] = Vec3(100, 100, 100);
  }
}

// The segment (0.5, 0, 0) -> (0.5, 1.2, 0) in 6 bins of 0.2, width 0.2: the last bin (y in
// [1, 1.2]) holds no particle.
ProfileLine line(const Vec3& direction, bool speed = false) {
  ProfileLine l;
  l.start = Vec3(0.5, 0.0, 0.0);
  l.end = Vec3(0.5, 1.2, 0.0);
  l.bins = 6;
  l.width = 0.2;
  l.speed = speed;
  l.direction = direction;
  return l;
}

TEST(VelocityProfile, ColumnsPerBin) {
  const VelocityProfile profile(line(Vec3::UnitX()));
  const std::vector<Column> columns = profile.columns();
  ASSERT_EQ(columns.size(), 6u);
  EXPECT_EQ(columns[0].name, "velocity_profile_0");
  EXPECT_EQ(columns[5].name, "velocity_profile_5");
  EXPECT_EQ(columns[3].unit, "m/s");
}

TEST(VelocityProfile, LinearShearAlongTheFlow) {
  ParticleStore store;
  shear(store);
  VelocityProfile profile(line(Vec3::UnitX()));
  const std::vector<double> values = sample_once(profile, store, 0.0);
  for (int b = 0; b < 5; ++b)
    EXPECT_NEAR(values[static_cast<std::size_t>(b)], kShearRate * (0.1 + 0.2 * b), kTight) << b;
  EXPECT_TRUE(std::isnan(values[5]));
}

TEST(VelocityProfile, OtherComponentsAndTheSpeed) {
  ParticleStore store;
  shear(store);
  VelocityProfile across(line(Vec3(0, 2, 0)));  // normalised to y
  VelocityProfile diagonal(line(Vec3(1, 1, 0)));
  const std::vector<double> v_y = sample_once(across, store, 0.0);
  const std::vector<double> v_d = sample_once(diagonal, store, 0.0);
  for (int b = 0; b < 5; ++b) {
    const auto k = static_cast<std::size_t>(b);
    EXPECT_NEAR(v_y[k], 3.0, kTight) << b;
    EXPECT_NEAR(v_d[k], (kShearRate * (0.1 + 0.2 * b) + 3.0) / std::sqrt(2.0), kTight) << b;
  }
  // The speed: bin 0 holds y = 0.02, 0.06, ..., 0.18, each 15 times.
  VelocityProfile speed(line(Vec3::UnitX(), true));
  double expected = 0.0;
  for (int j = 0; j < 5; ++j)
    expected += std::hypot(kShearRate * (0.02 + 0.04 * j), 3.0) / 5.0;
  EXPECT_NEAR(sample_once(speed, store, 0.0)[0], expected, kTight);
}

TEST(VelocityProfile, FinalFiguresAreTheLastSampleOfTheFilledBins) {
  ParticleStore store;
  shear(store);
  VelocityProfile profile(line(Vec3::UnitX()));
  Figures figures;
  profile.add_figures(figures);
  EXPECT_TRUE(figures.empty());
  sample_once(profile, store, 0.0);
  for (Vec3& v : store.velocity())
    v *= 2.0;
  sample_once(profile, store, 1.0);
  profile.add_figures(figures);
  ASSERT_EQ(figures.size(), 5u);  // bin 5 is empty
  EXPECT_NEAR(figures.at("velocity_profile_2_final"), 2.0 * kShearRate * 0.5, kTight);
  EXPECT_FALSE(figures.contains("velocity_profile_5_final"));
}

TEST(VelocityProfile, NarrowWidthTakesOnlyTheLine) {
  // width 0.01: only the particles on the line (x = 0.5, z = 0): the same means.
  ParticleStore store;
  shear(store);
  ProfileLine narrow = line(Vec3::UnitX());
  narrow.width = 0.01;
  VelocityProfile profile(narrow);
  const std::vector<double> values = sample_once(profile, store, 0.0);
  for (int b = 0; b < 5; ++b)
    EXPECT_NEAR(values[static_cast<std::size_t>(b)], kShearRate * (0.1 + 0.2 * b), kTight) << b;
}

TEST(VelocityProfile, BadLinesAreRefused) {
  ProfileLine l = line(Vec3::UnitX());
  l.end = l.start;
  EXPECT_THROW(VelocityProfile{l}, std::invalid_argument);
  l = line(Vec3::Zero());
  EXPECT_THROW(VelocityProfile{l}, std::invalid_argument);
  l = line(Vec3::UnitX());
  l.width = 0.0;
  EXPECT_THROW(VelocityProfile{l}, std::invalid_argument);
  l = line(Vec3::UnitX());
  l.bins = 0;
  EXPECT_THROW(VelocityProfile{l}, std::invalid_argument);
}

TEST(VelocityProfile, RegisteredByName) {
  AnalysisOptions options;
  options.profile = line(Vec3::UnitX());
  const auto analysis = analysis_registry().create("velocity_profile", options);
  ASSERT_NE(analysis, nullptr);
  EXPECT_EQ(analysis->columns().size(), 6u);
}

}  // namespace
}  // namespace partimix::analysis
