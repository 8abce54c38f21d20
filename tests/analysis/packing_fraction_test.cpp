// Packing fraction (docs/mixing.md, "Packing fraction"): spheres of diameter d on a simple cubic
// lattice of spacing d fill pi/6 of a box whose faces lie midway between lattice planes; a box
// whose faces pass through centres counts those spheres whole (the centre-in-box rule); discs on
// a square lattice in 2D fill pi/4; wall particles and particles outside do not count; no
// radius field is a RunError.
#include "analysis/packing_fraction.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "load_fixtures.hpp"

namespace partimix::analysis {
namespace {

using analysis_test::add_particle;
using analysis_test::sample_once;

constexpr double kPi = std::numbers::pi;
constexpr double kSpacing = 0.01;  // d

// n x n x n grains of radius d/2 at ((i + 1/2) d, (j + 1/2) d, (k + 1/2) d) (n x n at z = 0 in
// 2D), a wall particle and a grain outside the lattice's box.
void lattice(ParticleStore& store, int n, bool flat) {
  Field<double>& radius = store.add_scalar("radius", "m");
  for (int k = 0; k < (flat ? 1 : n); ++k) {
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) {
        const Vec3 x((i + 0.5) * kSpacing, (j + 0.5) * kSpacing, flat ? 0.0 : (k + 0.5) * kSpacing);
        radius.values[add_particle(store, ParticleKind::grain, x)] = 0.5 * kSpacing;
      }
    }
  }
  radius.values[add_particle(store, ParticleKind::wall, Vec3::Constant(0.5 * kSpacing))] = 1.0;
  radius.values[add_particle(store, ParticleKind::grain, Vec3::Constant(-kSpacing))] = 1.0;
}

PackingBox box(double lo, double hi, bool flat = false) {
  return {Vec3(lo, lo, flat ? 0.0 : lo), Vec3(hi, hi, flat ? 0.0 : hi)};
}

TEST(PackingFraction, SimpleCubicLatticeFillsPiOverSix) {
  // n^3 spheres of volume pi d^3 / 6 in the box [0, n d]^3.
  ParticleStore store;
  lattice(store, 6, false);
  PackingFraction packing(box(0.0, 6 * kSpacing));
  ASSERT_EQ(packing.columns().size(), 1u);
  EXPECT_EQ(packing.columns()[0].name, "packing_fraction");
  EXPECT_NEAR(sample_once(packing, store, 0.0)[0], kPi / 6.0, 1e-12);
  Figures figures;
  packing.add_figures(figures);
  EXPECT_NEAR(figures.at("packing_fraction_final"), kPi / 6.0, 1e-12);
}

TEST(PackingFraction, CentresOnTheFacesCountWhole) {
  // The box [d/2, 5.5 d]^3 has the outer centres on its faces: all 6^3 spheres count whole in a
  // box of (5 d)^3, so phi = (pi/6) 216/125, above the true pi/6: the centre-in-box rule.
  ParticleStore store;
  lattice(store, 6, false);
  PackingFraction packing(box(0.5 * kSpacing, 5.5 * kSpacing));
  EXPECT_NEAR(sample_once(packing, store, 0.0)[0], kPi / 6.0 * 216.0 / 125.0, 1e-12);
}

TEST(PackingFraction, SquareLatticeOfDiscsIn2D) {
  ParticleStore store;
  lattice(store, 5, true);
  PackingFraction packing(box(0.0, 5 * kSpacing, true));
  EXPECT_NEAR(sample_once(packing, store, 0.0)[0], kPi / 4.0, 1e-12);
}

TEST(PackingFraction, NoRadiusFieldIsARunError) {
  ParticleStore store;
  add_particle(store, ParticleKind::fluid, Vec3::Constant(0.5));
  PackingFraction packing(box(0.0, 1.0));
  try {
    sample_once(packing, store, 0.0);
    FAIL() << "no RunError";
  } catch (const RunError& error) {
    EXPECT_NE(std::string(error.what()).find("needs the particle field 'radius'"),
              std::string::npos);
  }
}

TEST(PackingFraction, BadBoxesAreRefused) {
  EXPECT_THROW(PackingFraction(PackingBox{Vec3(0, 0, 0), Vec3(1, 0, 1)}), std::invalid_argument);
  EXPECT_THROW(PackingFraction(PackingBox{Vec3(0, 0, 1), Vec3(1, 1, 0)}), std::invalid_argument);
}

TEST(PackingFraction, RegisteredByName) {
  AnalysisOptions options;
  options.packing = box(0.0, 6 * kSpacing);
  const auto analysis = analysis_registry().create("packing_fraction", options);
  ASSERT_NE(analysis, nullptr);
  ParticleStore store;
  lattice(store, 6, false);
  EXPECT_NEAR(sample_once(*analysis, store, 0.0)[0], kPi / 6.0, 1e-12);
}

}  // namespace
}  // namespace partimix::analysis
