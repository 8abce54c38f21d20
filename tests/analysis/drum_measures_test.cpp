// The truck drum's measurements (docs/truck-drum.md, "Measurements") on hand-placed grains in a
// tilted drum: the segregation degree of slices whose coarse shares alternate 0.4 and 0.6 is
// 100 sd / mean = 20% (1e-9), a uniform mixture's is 0 with empty slices left out, the summary
// takes the last sample before mixing_until and survives a replay; the discharge of two grains a
// second gives the rate 120 V_g m³/min and the flow column exactly, the residual rate 10% for 2
// of 20 grains left, and the uniformity test's difference 100 |a - b| / ((a + b) / 2) of the
// stream's coarse shares at a quarter (a = 1/2) and three quarters (b = 1) of the discharge.
// The random mixture's degree S_r: over 2,000 mixtures of 20 grains in each of 10 slices, each
// grain coarse with probability 0.3 (a fixed seed), the mean of S² is that of S_r² within 5%
// (expected 1.005 times it, the slices being drawn from the mixture as it came out; the ratio's
// own spread about 1.1%; measured 1.027), and S_r = 100 sqrt(9/100 · 10 · 0.21 / 10) / 0.3 = 45.8%
// for a set of ten slices of ten grains, three coarse in each. segregation_mean averages S from
// average_from.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>
#include <random>
#include <vector>

#include "analysis/drum_discharge.hpp"
#include "analysis/drum_segregation.hpp"
#include "load_fixtures.hpp"

namespace partimix::analysis {
namespace {

using analysis_test::add_particle;
using analysis_test::sample_once;

constexpr double kRadius = 0.002;
const Vec3 kHead(0.1, -0.2, 0.3);

std::shared_ptr<const geometry::TruckDrumShape> drum() {
  geometry::TruckDrumParameters p;
  p.head_radius = 0.05;
  p.front_length = 0.05;
  p.radius = 0.08;
  p.cylinder_length = 0.1;
  p.rear_length = 0.05;
  p.opening_radius = 0.03;
  p.helix_angle = 70.0 * std::numbers::pi / 180.0;
  p.blade_height = 0.02;
  p.blade_thickness = 0.004;
  p.offset_angles = {0.0, 0.0, 0.0};
  static const auto shape =
      std::make_shared<const geometry::TruckDrumShape>(p, kHead, Vec3(1.0, 0.0, 0.2), 24);
  return shape;
}

// The case's point at (z, θ, ρ) of the drum's frame.
Vec3 at(double z, double theta, double rho) {
  return drum()->from_drum(Vec3(rho * std::cos(theta), rho * std::sin(theta), z));
}

struct Grains {
  ParticleStore store;
  Field<double>* radius = &store.add_scalar("radius", "m");
  Field<std::int32_t>* species = &store.add_integer("species", "");

  void add(const Vec3& x, int kind) {
    const std::size_t i = add_particle(store, ParticleKind::grain, x);
    radius->values[i] = kRadius;
    species->values[i] = kind;
  }
};

DrumMeasures options() {
  DrumMeasures o;
  o.drum = drum();
  o.bins = 10;
  o.coarse_species = 1;
  return o;
}

// Ten grains in each of the first `slices` of ten slices, `coarse(k)` of them coarse.
template <class Coarse>
void fill_slices(Grains& grains, int slices, Coarse coarse) {
  const double length = drum()->drum().length();
  for (int k = 0; k < slices; ++k)
    for (int g = 0; g < 10; ++g)
      grains.add(at((k + 0.5) * length / 10, 0.6 * g, 0.01), g < coarse(k) ? 1 : 0);
}

TEST(DrumSegregation, AlternatingSharesGiveTheirCoefficientOfVariation) {
  Grains grains;
  fill_slices(grains, 10, [](int k) { return k % 2 == 0 ? 4 : 6; });
  grains.add(at(drum()->drum().length() + 0.05, 0.0, 0.0), 1);  // discharged: not counted
  DrumSegregation segregation(options());
  const std::vector<double> values = sample_once(segregation, grains.store, 0.0);
  EXPECT_NEAR(values[0], 20.0, 1e-9);
  EXPECT_NEAR(values[1], 0.5, 1e-12);
}

TEST(DrumSegregation, AUniformMixtureIsZeroAndEmptySlicesAreLeftOut) {
  Grains grains;
  fill_slices(grains, 9, [](int) { return 3; });
  DrumSegregation segregation(options());
  EXPECT_NEAR(sample_once(segregation, grains.store, 0.0)[0], 0.0, 1e-9);
  Figures figures;
  segregation.add_figures(figures);
  EXPECT_EQ(figures.at("segregation_within_threshold"), 1.0);
}

// Slices whose coarse shares alternate 0.4 and 0.6 (S = 20%), and a uniform mixture (S = 0).
struct TwoMixtures {
  Grains segregated;
  Grains uniform;
  TwoMixtures() {
    fill_slices(segregated, 10, [](int k) { return k % 2 == 0 ? 4 : 6; });
    fill_slices(uniform, 10, [](int) { return 5; });
  }
};

TEST(DrumSegregation, TheSummaryIsTheLastSampleBeforeMixingUntilAndSurvivesAReplay) {
  const TwoMixtures mixtures;
  const Grains& segregated = mixtures.segregated;
  const Grains& uniform = mixtures.uniform;
  DrumMeasures o = options();
  o.mixing_until = 1.5;
  DrumSegregation segregation(o);
  const std::vector<double> first = sample_once(segregation, segregated.store, 1.0);
  const std::vector<double> second = sample_once(segregation, uniform.store, 2.0);
  Figures figures;
  segregation.add_figures(figures);
  EXPECT_NEAR(figures.at("segregation_degree"), 20.0, 1e-9);
  EXPECT_EQ(figures.at("segregation_within_threshold"), 0.0);
  DrumSegregation replayed(o);
  replayed.replay(1.0, first);
  replayed.replay(2.0, second);
  Figures again;
  replayed.add_figures(again);
  EXPECT_EQ(again.values(), figures.values());
}

// Twenty grains in each of ten slices, each coarse with probability `p`.
void fill_at_random(Grains& grains, double p, std::mt19937& random) {
  std::bernoulli_distribution coarse(p);
  const double length = drum()->drum().length();
  for (int k = 0; k < 10; ++k)
    for (int g = 0; g < 20; ++g)
      grains.add(at((k + 0.5) * length / 10, 0.3 * g, 0.01), coarse(random) ? 1 : 0);
}

TEST(DrumSegregation, ARandomMixtureShowsTheRandomDegreeOnAverage) {
  std::mt19937 random(20261130);
  DrumSegregation segregation(options());
  double squares = 0.0;
  double random_squares = 0.0;
  constexpr int kMixtures = 2000;
  for (int n = 0; n < kMixtures; ++n) {
    Grains grains;
    fill_at_random(grains, 0.3, random);
    const std::vector<double> values = sample_once(segregation, grains.store, 0.0);
    squares += values[0] * values[0];
    random_squares += values[2] * values[2];
  }
  std::printf("mean S^2 %.2f, mean S_r^2 %.2f\n", squares / kMixtures, random_squares / kMixtures);
  EXPECT_NEAR(squares / random_squares, 1.0, 0.05);
  Grains exact;
  fill_slices(exact, 10, [](int) { return 3; });
  const double expected = 100.0 * std::sqrt(9.0 / 100.0 * 10.0 * 0.21 / 10.0) / 0.3;
  EXPECT_NEAR(sample_once(segregation, exact.store, 0.0)[2], expected, 1e-9);
}

TEST(DrumSegregation, TheMeanIsOverTheSamplesFromAverageFromToMixingUntil) {
  const TwoMixtures mixtures;
  const Grains& segregated = mixtures.segregated;
  const Grains& uniform = mixtures.uniform;
  DrumMeasures o = options();
  o.average_from = 1.0;
  o.mixing_until = 3.0;
  DrumSegregation segregation(o);
  sample_once(segregation, uniform.store, 0.0);     // before: not averaged
  sample_once(segregation, segregated.store, 1.0);  // 20%
  sample_once(segregation, uniform.store, 2.0);     // 0%
  sample_once(segregation, uniform.store, 3.0);     // 0%
  sample_once(segregation, segregated.store, 4.0);  // after: not averaged
  Figures figures;
  segregation.add_figures(figures);
  EXPECT_NEAR(figures.at("segregation_mean"), 20.0 / 3.0, 1e-9);
  EXPECT_NEAR(figures.at("segregation_degree"), 0.0, 1e-9);
}

TEST(DrumDischarge, RateResidualAndUniformityOfATwoGrainsASecondDischarge) {
  const double length = drum()->drum().length();
  const double grain = 4.0 / 3.0 * std::numbers::pi * std::pow(kRadius, 3);
  Grains grains;
  for (int g = 0; g < 20; ++g)
    grains.add(at(0.02 + 0.008 * g, 0.3 * g, 0.01), 0);
  // Grains 2 and 3 leave at t = 2 (a quarter of the 18 discharged), 12 and 13 at t = 7.
  for (int g : {2, 12, 13})
    grains.species->values[g] = 1;
  DrumMeasures o = options();
  DrumDischarge discharge(o);
  std::vector<std::vector<double>> rows;
  for (int t = 0; t <= 9; ++t) {
    for (int g = 0; g < 2 * t; ++g) {
      const bool just_out = g >= 2 * t - 2;
      grains.store.position()[g] = at(length + (just_out ? 0.01 : 1.0), 0.0, 0.0);
    }
    rows.push_back(sample_once(discharge, grains.store, t));
    EXPECT_NEAR(rows.back()[1], 2 * t * grain, 1e-18) << t;
    EXPECT_NEAR(rows.back()[2], t == 0 ? 0.0 : 120.0 * grain, 1e-15) << t;
  }
  EXPECT_NEAR(rows[2][4], 0.5, 1e-12);
  Figures figures;
  discharge.add_figures(figures);
  EXPECT_NEAR(figures.at("residual_rate"), 10.0, 1e-9);
  EXPECT_NEAR(figures.at("discharge_rate"), 120.0 * grain, 1e-12 * grain);
  EXPECT_NEAR(figures.at("coarse_aggregate_difference"), 100.0 * 0.5 / 0.75, 1e-9);
  Caveats caveats;
  discharge.add_caveats(caveats);
  EXPECT_TRUE(caveats.empty());
}

TEST(DrumDischarge, NoStreamSampleIsACaveat) {
  Grains grains;
  grains.add(at(0.05, 0.0, 0.01), 1);
  DrumDischarge discharge(options());
  for (int t = 0; t < 4; ++t)
    sample_once(discharge, grains.store, t);
  Caveats caveats;
  discharge.add_caveats(caveats);
  EXPECT_TRUE(caveats.contains("coarse_aggregate_difference"));
  Figures figures;
  discharge.add_figures(figures);
  EXPECT_NEAR(figures.at("residual_rate"), 100.0, 1e-12);
  EXPECT_FALSE(figures.contains("coarse_aggregate_difference"));
}

// A grid fluid's cells carry the fluid's volume (the mortar's with two phases) and no species:
// three cells of 1, 2 and 3 cm³ in the cavity, the 3 cm³ one then past the opening.
TEST(DrumDischarge, CellsCarryingAVolumeWithoutSpeciesAreMeasured) {
  ParticleStore cells;
  Field<double>& volume = cells.add_scalar("volume", "m^3");
  for (int c = 0; c < 3; ++c) {
    const std::size_t i = add_particle(cells, ParticleKind::fluid, at(0.05 + 0.05 * c, 0.0, 0.01));
    volume.values[i] = 1e-6 * (c + 1);
  }
  DrumDischarge discharge(options());
  EXPECT_NEAR(sample_once(discharge, cells, 0.0)[0], 6e-6, 1e-18);
  cells.position()[2] = at(drum()->drum().length() + 0.01, 0.0, 0.0);
  const std::vector<double> row = sample_once(discharge, cells, 1.0);
  EXPECT_NEAR(row[0], 3e-6, 1e-18);
  EXPECT_NEAR(row[1], 3e-6, 1e-18);
  EXPECT_NEAR(row[3], 3e-6, 1e-18);  // in the stream
  EXPECT_EQ(row[4], 0.0);            // none of it coarse aggregate
  Figures figures;
  discharge.add_figures(figures);
  EXPECT_NEAR(figures.at("residual_rate"), 50.0, 1e-9);
  EXPECT_FALSE(figures.contains("coarse_aggregate_difference"));
}

}  // namespace
}  // namespace partimix::analysis
