// Kinetic energy (src/analysis/kinetic_energy.hpp): translation sum m |v|^2 / 2 over the
// material particles; with the grain fields "radius" and "angular_velocity" also the rotation of
// solid spheres, sum (1/5) m R^2 |w|^2, as its own column; a store without them (SPH, even with
// the angular velocities MovingBodies gives wall particles) keeps the one column.
#include "analysis/kinetic_energy.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "load_fixtures.hpp"

namespace partimix::analysis {
namespace {

using analysis_test::add_particle;
using analysis_test::sample_once;

constexpr double kTight = 1e-14;

// Two grains and a wall particle (which must not count), with or without the grain fields:
//   grain 0: m = 2, v = (1, 2, 0),  R = 0.1, w = (0, 0, 10): translation 5,  rotation 0.4
//   grain 1: m = 1, v = (0, 0, -3), R = 0.2, w = (3, 4, 0):  translation 4.5, rotation 0.2
//   wall:    m = 7, v = (5, 0, 0),  R = 1,   w = (0, 0, 9)
// so E = 9.5 J and E_rot = 0.2 (2 0.01 100 + 1 0.04 25) = 0.6 J.
void fill(ParticleStore& store, bool radius, bool angular_velocity) {
  Field<double>* r = radius ? &store.add_scalar("radius", "m") : nullptr;
  Field<Vec3>* w = angular_velocity ? &store.add_vector("angular_velocity", "rad/s") : nullptr;
  const struct {
    ParticleKind kind;
    double mass;
    Vec3 v;
    double radius;
    Vec3 omega;
  } particles[] = {{ParticleKind::grain, 2.0, Vec3(1, 2, 0), 0.1, Vec3(0, 0, 10)},
                   {ParticleKind::wall, 7.0, Vec3(5, 0, 0), 1.0, Vec3(0, 0, 9)},
                   {ParticleKind::grain, 1.0, Vec3(0, 0, -3), 0.2, Vec3(3, 4, 0)}};
  for (const auto& p : particles) {
    const std::size_t i = add_particle(store, p.kind, Vec3::Zero());
    store.mass()[i] = p.mass;
    store.velocity()[i] = p.v;
    if (r != nullptr)
      r->values[i] = p.radius;
    if (w != nullptr)
      w->values[i] = p.omega;
  }
}

TEST(KineticEnergy, GrainsGetARotationalColumn) {
  ParticleStore store;
  fill(store, true, true);
  KineticEnergy energy(store);
  EXPECT_TRUE(energy.rotational());
  const std::vector<Column> columns = energy.columns();
  ASSERT_EQ(columns.size(), 2u);
  EXPECT_EQ(columns[0].name, "kinetic_energy");
  EXPECT_EQ(columns[1].name, "rotational_energy");
  EXPECT_EQ(columns[1].unit, "J");
  const std::vector<double> values = sample_once(energy, store, 0.0);
  EXPECT_NEAR(values[0], 9.5, kTight);
  EXPECT_NEAR(values[1], 0.6, kTight);
}

// Superquadric runs carry each grain's world angular momentum L: the rotational energy is then
// w . L / 2, with the full inertia tensor (here L = diag(1, 2, 3) w per grain).
TEST(KineticEnergy, WithAngularMomentaTheFullInertiaTensor) {
  ParticleStore store;
  fill(store, true, true);
  auto& momentum = store.add_vector("angular_momentum", "kg m^2/s", false).values;
  const auto& omega = store.find_vector("angular_velocity")->values;
  double expected = 0.0;
  for (std::size_t i = 0; i < store.size(); ++i) {
    momentum[i] = Vec3(1, 2, 3).cwiseProduct(omega[i]);
    if (store.is_material(i))
      expected += 0.5 * omega[i].dot(momentum[i]);
  }
  KineticEnergy energy(store);
  EXPECT_NEAR(sample_once(energy, store, 0.0)[1], expected, kTight);
  EXPECT_GT(expected, 0.0);
}

TEST(KineticEnergy, WithoutBothFieldsOnlyTranslation) {
  // SPH with turning bodies has angular_velocity (on wall particles) but no radius.
  for (const auto& [radius, omega] : {std::pair{false, false}, {false, true}, {true, false}}) {
    ParticleStore store;
    fill(store, radius, omega);
    KineticEnergy energy(store);
    EXPECT_FALSE(energy.rotational());
    ASSERT_EQ(energy.columns().size(), 1u);
    EXPECT_EQ(energy.columns()[0].name, "kinetic_energy");
    EXPECT_NEAR(sample_once(energy, store, 0.0)[0], 9.5, kTight);
  }
  ParticleStore grains;
  fill(grains, true, true);
  KineticEnergy translation_only;  // the default: as before
  ASSERT_EQ(translation_only.columns().size(), 1u);
  EXPECT_NEAR(sample_once(translation_only, grains, 0.0)[0], 9.5, kTight);
}

TEST(KineticEnergy, RotationalColumnIsNanForAStoreWithoutTheFields) {
  ParticleStore grains;
  fill(grains, true, true);
  KineticEnergy energy(grains);
  ParticleStore fluid;
  fill(fluid, false, false);
  const std::vector<double> values = sample_once(energy, fluid, 0.0);
  EXPECT_NEAR(values[0], 9.5, kTight);
  EXPECT_TRUE(std::isnan(values[1]));
}

}  // namespace
}  // namespace partimix::analysis
