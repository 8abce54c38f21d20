// Packing fraction (docs/mixing.md, "Packing fraction"): spheres of diameter d on a simple cubic
// lattice of spacing d fill pi/6 of a box whose faces lie midway between lattice planes; a box
// whose faces pass through centres counts those spheres whole (the centre-in-box rule); discs on
// a square lattice in 2D fill pi/4; wall particles and particles outside do not count; no
// radius field is a RunError. Blocky superquadric grains (n1 = 4, n2 = 6) placed by the DEM
// solver on a lattice, turned at random, fill N V / V_box with V their true volume (to 1e-12),
// not the volume of their bounding spheres (the field radius).
#include "analysis/packing_fraction.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "core/error.hpp"
#include "dem/dem_solver.hpp"
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

TEST(PackingFraction, SuperquadricGrainsCountTheirTrueVolume) {
  // 4 x 4 x 4 grains of half-axes 1, 1.5, 2 mm at the centres of cells of 5 mm.
  const dem::Superquadric blocky(Vec3(1.0e-3, 1.5e-3, 2.0e-3), 4.0, 6.0);
  dem::Config config;
  config.species = {dem::Species{"blocky", 2500.0, {1.0e7, 0.3}, blocky}};
  config.particle_interactions = {dem::Interaction{}};
  config.wall_interactions = {dem::Interaction{}};
  constexpr int kSide = 4;
  constexpr double kCell = 5.0e-3;
  dem::Grains grains;
  for (int n = 0; n < kSide * kSide * kSide; ++n) {
    grains.position.push_back(
        kCell * Vec3(n % kSide + 0.5, n / kSide % kSide + 0.5, n / (kSide * kSide) + 0.5));
    grains.radius.push_back(0.0);
    grains.species.push_back(0);
    grains.orientation.push_back(Eigen::Quaterniond(
        Eigen::AngleAxisd(0.37 * n, Vec3(std::sin(n), std::cos(n), 0.5).normalized())));
  }
  Domain domain;
  domain.lo = Vec3::Constant(-0.01);
  domain.hi = Vec3::Constant(0.03);
  ParticleStore store;
  const dem::DemSolver solver(store, domain, config, Vec3::Zero(), grains);
  PackingFraction packing(box(0.0, kSide * kCell));
  const double box_volume = std::pow(kSide * kCell, 3);
  const double expected = kSide * kSide * kSide * blocky.volume() / box_volume;
  EXPECT_NEAR(sample_once(packing, store, 0.0)[0], expected, 1e-12 * expected);
  const double bounding = 4.0 / 3.0 * kPi * std::pow(blocky.bounding_radius(), 3);
  EXPECT_GT(bounding, 4.0 * blocky.volume());  // what the radius field would have given
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
