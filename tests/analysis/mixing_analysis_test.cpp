// The mixing analysis (docs/mixing.md): tag 1 marks the tracer fluid, wall particles and
// particles outside the region count nowhere, and xi and the Lacey index of a 2D disc cut into
// two half-disc sectors (and of a box cut into halves) take the values worked out by hand for a
// segregated and a mixed state; min_count reaches the Lacey index; the summary holds the last
// values and the mixing-rate fits of the sampled Lacey index.
#include "analysis/mixing.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "analysis/mixing_rate.hpp"
#include "load_fixtures.hpp"

namespace partimix::analysis {
namespace {

using analysis_test::add_particle;
using analysis_test::sample_once;

constexpr double kTight = 1e-12;

// The unit disc about the origin as a 2D run gives it (z in [-1, 1]), cut into one ring and
// two sectors: sector 0 is y > 0 (theta in [0, pi)), sector 1 is y < 0.
MixingRegion half_discs(int min_count = 1) {
  MixingRegion region;
  region.cylinder_region.radius = 1.0;
  region.cylinder_region.z0 = -1.0;
  region.cylinder_region.z1 = 1.0;
  region.cells = {1, 2, 1};
  region.min_count = min_count;
  return region;
}

// Four fluid particles in each half disc, tagged by `upper_tags` and `lower_tags`; wall
// particles tagged 1 in both halves and a tagged fluid particle outside the disc, none of which
// may count.
void fill(ParticleStore& store, const std::vector<int>& upper_tags,
          const std::vector<int>& lower_tags) {
  const double xs[] = {0.5, -0.5, 0.2, -0.2};
  const double ys[] = {0.5, 0.5, 0.2, 0.2};
  for (std::size_t k = 0; k < 4; ++k) {
    add_particle(store, ParticleKind::fluid, Vec3(xs[k], ys[k], 0), upper_tags[k]);
    add_particle(store, ParticleKind::fluid, Vec3(xs[k], -ys[k], 0), lower_tags[k]);
  }
  add_particle(store, ParticleKind::wall, Vec3(0.1, 0.8, 0), 1);
  add_particle(store, ParticleKind::wall, Vec3(0.1, -0.8, 0), 1);
  add_particle(store, ParticleKind::fluid, Vec3(2.0, 0.1, 0), 1);
}

TEST(MixingAnalysis, ColumnsAreXiAndLaceyWithoutUnits) {
  const Mixing mixing(half_discs());
  const std::vector<Column> columns = mixing.columns();
  ASSERT_EQ(columns.size(), 2u);
  EXPECT_EQ(columns[0].name, "xi");
  EXPECT_EQ(columns[1].name, "lacey");
  EXPECT_EQ(columns[0].unit, "");
  EXPECT_EQ(columns[1].unit, "");
  EXPECT_FALSE(mixing.needs_body_forces());
}

TEST(MixingAnalysis, TracersAllInOneHalfAreSegregated) {
  // Tracers N = (0, 4) in n = 2 cells, N0 = 4, Nbar = 2:
  //   xi = ((0 - 2)^2 + (4 - 2)^2) / ((2 - 1) 16) = 0.5 = 1/n.
  // Lacey: 4 particles per cell, C = 2, p = 4/8 = 0.5, nbar = 4, phi = (0, 1), mean 0.5:
  //   S^2 = (0.25 + 0.25)/(2 - 1) = 0.5, S0^2 = 0.25, Sr^2 = 0.25/4 = 0.0625,
  //   M = (0.25 - 0.5)/(0.25 - 0.0625) = -4/3 (= -nbar/((C - 1)(nbar - 1))).
  ParticleStore store;
  fill(store, {0, 0, 0, 0}, {1, 1, 1, 1});
  Mixing mixing(half_discs());
  const std::vector<double> values = sample_once(mixing, store, 0.0);
  EXPECT_NEAR(values[0], 0.5, kTight);
  EXPECT_NEAR(values[1], -4.0 / 3.0, kTight);
}

TEST(MixingAnalysis, TwoTracersInEachHalfAreMixed) {
  // N = (2, 2): xi = 0. phi = (0.5, 0.5): S^2 = 0, M = 0.25/0.1875 = 4/3 (= nbar/(nbar - 1)).
  ParticleStore store;
  fill(store, {1, 0, 1, 0}, {0, 1, 0, 1});
  Mixing mixing(half_discs());
  const std::vector<double> values = sample_once(mixing, store, 0.0);
  EXPECT_NEAR(values[0], 0.0, kTight);
  EXPECT_NEAR(values[1], 4.0 / 3.0, kTight);
}

TEST(MixingAnalysis, MinCountLeavesSparseCellsOutOfLacey) {
  // min_count 5 > 4 particles per cell: no counted cell, so M is NaN; xi counts every cell.
  ParticleStore store;
  fill(store, {0, 0, 0, 0}, {1, 1, 1, 1});
  Mixing mixing(half_discs(5));
  const std::vector<double> values = sample_once(mixing, store, 0.0);
  EXPECT_NEAR(values[0], 0.5, kTight);
  EXPECT_TRUE(std::isnan(values[1]));
}

TEST(MixingAnalysis, BoxHalvesOfA2DRun) {
  // The box [-1, 1] x [-1, 1] x [0, 0] (flat z) cut into 2 x 1 x 1: x < 0 and x > 0. The
  // tracers are the four fluid particles at x > 0 (tags by position): each half holds 4, the
  // tracers N = (0, 4): xi = 0.5, M = -4/3 as for the half discs.
  ParticleStore store;
  fill(store, {1, 0, 1, 0}, {1, 0, 1, 0});
  MixingRegion region;
  region.cylinder = false;
  region.lo = Vec3(-1, -1, 0);
  region.hi = Vec3(1, 1, 0);
  region.cells = {2, 1, 1};
  Mixing mixing(region);
  const std::vector<double> values = sample_once(mixing, store, 0.0);
  EXPECT_NEAR(values[0], 0.5, kTight);
  EXPECT_NEAR(values[1], -4.0 / 3.0, kTight);
}

TEST(MixingAnalysis, FiguresAreTheLastValues) {
  Mixing mixing(half_discs());
  Figures figures;
  mixing.add_figures(figures);
  EXPECT_TRUE(std::isnan(figures.at("xi_final")));  // not sampled yet
  ParticleStore segregated;
  fill(segregated, {0, 0, 0, 0}, {1, 1, 1, 1});
  ParticleStore mixed;
  fill(mixed, {1, 0, 1, 0}, {0, 1, 0, 1});
  sample_once(mixing, segregated, 0.0);
  sample_once(mixing, mixed, 1.0);
  mixing.add_figures(figures);
  EXPECT_NEAR(figures.at("xi_final"), 0.0, kTight);
  EXPECT_NEAR(figures.at("lacey_final"), 4.0 / 3.0, kTight);
  // Two samples are too few for a mixing-rate fit: it adds no figures (run.json's figures stay
  // finite).
  EXPECT_EQ(figures.size(), 2u);
}

TEST(MixingAnalysis, MixingRateFiguresFitTheSampledLaceyIndex) {
  // Samples at t = 0 (segregated, M = -4/3), 1, 2, 3, 4 (mixed, M = 4/3) and a state with no
  // tracer at t = 5 (M NaN, skipped): the figures are the fits of these (t, M) pairs.
  Mixing mixing(half_discs());
  ParticleStore segregated;
  fill(segregated, {0, 0, 0, 0}, {1, 1, 1, 1});
  ParticleStore mixed;
  fill(mixed, {1, 0, 1, 0}, {0, 1, 0, 1});
  ParticleStore untagged;
  fill(untagged, {0, 0, 0, 0}, {0, 0, 0, 0});
  sample_once(mixing, segregated, 0.0);
  for (const double t : {1.0, 2.0, 3.0, 4.0})
    sample_once(mixing, mixed, t);
  EXPECT_TRUE(std::isnan(sample_once(mixing, untagged, 5.0)[1]));
  Figures figures;
  mixing.add_figures(figures);
  EXPECT_EQ(figures.size(), 23u);  // xi_final, lacey_final and 7 for each of 3 models
  const std::vector<double> times{0, 1, 2, 3, 4};
  const std::vector<double> laceys{-4.0 / 3.0, 4.0 / 3.0, 4.0 / 3.0, 4.0 / 3.0, 4.0 / 3.0};
  for (const MixingModel model :
       {MixingModel::exponential, MixingModel::error_function, MixingModel::diffusive}) {
    const MixingRateFit fit = fit_mixing_rate(times, laceys, model, 1.0);
    ASSERT_EQ(fit.status, MixingFitStatus::ok);
    const std::string suffix = mixing_model_suffix(model);
    EXPECT_DOUBLE_EQ(figures.at("lacey_rate_" + suffix), fit.rate) << suffix;
    EXPECT_DOUBLE_EQ(figures.at("lacey_initial_" + suffix), fit.initial) << suffix;
    EXPECT_DOUBLE_EQ(figures.at("lacey_plateau_" + suffix), fit.plateau) << suffix;
    EXPECT_DOUBLE_EQ(figures.at("lacey_fit_r2_" + suffix), fit.r_squared) << suffix;
    EXPECT_DOUBLE_EQ(figures.at("lacey_fit_rms_" + suffix), fit.rms) << suffix;
    EXPECT_EQ(figures.at("lacey_fit_at_limit_" + suffix), 1.0) << suffix;
    EXPECT_EQ(figures.at("lacey_plateau_bounded_" + suffix), 1.0) << suffix;
    // A step from -4/3 to 4/3 before the second sample: M_0 = -4/3, the plateau held at the
    // Lacey index of a random mixture, 1, and k not bounded by the data.
    EXPECT_NEAR(fit.initial, -4.0 / 3.0, 1e-6) << suffix;
    EXPECT_DOUBLE_EQ(fit.plateau, 1.0) << suffix;
    EXPECT_TRUE(fit.plateau_bounded) << suffix;
    EXPECT_TRUE(fit.at_search_limit) << suffix;
  }
}

}  // namespace
}  // namespace partimix::analysis
