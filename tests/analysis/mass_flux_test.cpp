// Mass flux through a plane (docs/mixing.md, "Mass flux through a plane"). The plane y = 0 with
// the normal -y (the way a hopper's material leaves) and a band 0.2 m wide: three material points
// inside the band (masses 1, 2, 3 kg moving down at 1, 2, 0.5 m/s: -v.n = 1, 2, 0.5), one outside
// it (y = 0.15) and one wall particle inside it, both ignored. Q = (1 + 4 + 1.5) / 0.2 =
// 32.5 kg/s. Then the points move up at 1 m/s: Q = -30 kg/s. The mean from average_from = 0.5 s
// takes the second sample only. Tolerance 1e-12: round-off only.
#include "analysis/mass_flux.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

#include "load_fixtures.hpp"

namespace partimix::analysis {
namespace {

using analysis_test::add_particle;
using analysis_test::sample_once;

void fill_band(ParticleStore& store) {
  const double masses[] = {1.0, 2.0, 3.0};
  const double speeds[] = {1.0, 2.0, 0.5};
  for (int k = 0; k < 3; ++k) {
    const std::size_t i = add_particle(store, ParticleKind::material_point, Vec3(k, 0.04 * k, 0));
    store.mass()[i] = masses[k];
    store.velocity()[i] = Vec3(0.3, -speeds[k], 0);
  }
  const std::size_t far = add_particle(store, ParticleKind::material_point, Vec3(0, 0.15, 0));
  store.mass()[far] = 10.0;
  store.velocity()[far] = Vec3(0, -5, 0);
  const std::size_t wall = add_particle(store, ParticleKind::wall, Vec3(0, 0, 0));
  store.mass()[wall] = 10.0;
  store.velocity()[wall] = Vec3(0, -5, 0);
}

FluxPlane plane() {
  FluxPlane p;
  p.normal = -Vec3::UnitY();
  p.width = 0.2;
  p.average_from = 0.5;
  return p;
}

TEST(MassFlux, SumsTheBandsMassFluxOverItsWidth) {
  ParticleStore store;
  fill_band(store);
  MassFlux flux(plane());
  EXPECT_NEAR(sample_once(flux, store, 0.0)[0], 32.5, 1e-12);
  for (int k = 0; k < 3; ++k)
    store.velocity()[static_cast<std::size_t>(k)] = Vec3(0, 1, 0);
  EXPECT_NEAR(sample_once(flux, store, 1.0)[0], -30.0, 1e-12);
  Figures figures;
  flux.add_figures(figures);
  EXPECT_NEAR(figures.at("mean_mass_flux"), -30.0, 1e-12);

  MassFlux replayed(plane());
  const double first[] = {32.5};
  const double second[] = {-30.0};
  replayed.replay(0.0, first);
  replayed.replay(1.0, second);
  Figures again;
  replayed.add_figures(again);
  EXPECT_EQ(again.at("mean_mass_flux"), figures.at("mean_mass_flux"));
}

TEST(MassFlux, RefusesAZeroWidth) {
  FluxPlane p = plane();
  p.width = 0.0;
  EXPECT_THROW(MassFlux{p}, std::invalid_argument);
}

}  // namespace
}  // namespace partimix::analysis
