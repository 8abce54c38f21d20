// The automatic speed of sound (sph/sound_speed.hpp, docs/sph.md "Speed of sound"): the largest
// of Morris, Fox & Zhu's (1997) inertial, viscous and gravity criteria, each checked where it
// governs on a fluid block of known size; a given sound speed is taken as it is.
#include <gtest/gtest.h>

#include <cmath>

#include "sph/sound_speed.hpp"

namespace partimix::sph {
namespace {

constexpr double kSpacing = 0.01;

// Fluid particles on a lattice filling [0, nx dp) x [0, ny dp) x [0, nz dp).
void fill_block(ParticleStore& store, int nx, int ny, int nz) {
  store.resize(static_cast<std::size_t>(nx * ny * nz));
  std::size_t n = 0;
  for (int i = 0; i < nx; ++i) {
    for (int j = 0; j < ny; ++j) {
      for (int k = 0; k < nz; ++k, ++n) {
        store.kind()[n] = static_cast<std::int32_t>(ParticleKind::fluid);
        store.position()[n] = kSpacing * Vec3(i + 0.5, j + 0.5, k + 0.5);
      }
    }
  }
}

materials::BoundedRheology newtonian(double viscosity) {
  materials::RheologyConfig config;
  config.viscosity = viscosity;
  return materials::BoundedRheology(config);
}

Config with_velocity(double max_velocity) {
  Config config;
  config.spacing = kSpacing;
  config.max_velocity = max_velocity;
  return config;
}

TEST(SoundSpeed, InertiaGovernsAFastThinFlow) {
  ParticleStore store;
  fill_block(store, 10, 20, 30);
  const double c0 =
      resolve_sound_speed(with_velocity(2.0), store, Vec3::Zero(), newtonian(1e-3), 1000.0, 3);
  EXPECT_DOUBLE_EQ(c0, 20.0);
}

TEST(SoundSpeed, ViscosityGovernsASlowViscousFlowAcrossTheNarrowestExtent) {
  ParticleStore store;
  fill_block(store, 10, 20, 30);  // narrowest extent 0.1 m
  // nu U / L = (10 / 1000) 0.01 / 0.1 = 1e-3: c0 = 10 sqrt(1e-3) against 10 U = 0.1.
  const double c0 =
      resolve_sound_speed(with_velocity(0.01), store, Vec3::Zero(), newtonian(10.0), 1000.0, 3);
  EXPECT_NEAR(c0, 10.0 * std::sqrt(1e-3), 1e-12);
  Config given_length = with_velocity(0.01);
  given_length.flow_length = 0.01;
  EXPECT_NEAR(resolve_sound_speed(given_length, store, Vec3::Zero(), newtonian(10.0), 1000.0, 3),
              10.0 * std::sqrt(1e-2), 1e-12);
}

TEST(SoundSpeed, ThePowerLawViscosityIsTakenAtTheFlowsShearRate) {
  ParticleStore store;
  fill_block(store, 10, 20, 30);
  materials::RheologyConfig power_law;
  power_law.model = "power_law";
  power_law.consistency = 10.0;
  power_law.flow_index = 0.5;
  // Shear rate U / L = 0.1 1/s, eta = 10 0.1^-0.5, nu U / L = eta / 1000 * 0.1.
  const double expected = 10.0 * std::sqrt(10.0 * std::pow(0.1, -0.5) / 1000.0 * 0.1);
  EXPECT_NEAR(resolve_sound_speed(with_velocity(0.01), store, Vec3::Zero(),
                                  materials::BoundedRheology(power_law), 1000.0, 3),
              expected, 1e-12);
}

TEST(SoundSpeed, GravityGovernsASlowFlowUnderADeepColumn) {
  ParticleStore store;
  fill_block(store, 10, 10, 100);  // 1 m deep
  const double c0 = resolve_sound_speed(with_velocity(0.1), store, Vec3(0.0, 0.0, -9.81),
                                        newtonian(1e-3), 1000.0, 3);
  EXPECT_NEAR(c0, 10.0 * std::sqrt(9.81 * 1.0), 1e-12);
  // Without a given speed the dam-break front 2 sqrt(g H) governs: 20 sqrt(g H).
  Config estimated = with_velocity(0.1);
  estimated.max_velocity.reset();
  EXPECT_NEAR(
      resolve_sound_speed(estimated, store, Vec3(0.0, 0.0, -9.81), newtonian(1e-3), 1000.0, 3),
      20.0 * std::sqrt(9.81), 1e-12);
}

TEST(SoundSpeed, AGivenSoundSpeedIsTakenAsItIs) {
  ParticleStore store;
  fill_block(store, 10, 10, 10);
  Config config = with_velocity(0.01);
  config.sound_speed = 3.0;
  EXPECT_EQ(resolve_sound_speed(config, store, Vec3::Zero(), newtonian(100.0), 1000.0, 3), 3.0);
}

}  // namespace
}  // namespace partimix::sph
