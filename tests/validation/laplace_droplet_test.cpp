// The Laplace pressure of a static droplet on the multi-material scheme
// (docs/multi-material-sph.md, "Validation"): a disc (2D) or a sphere (3D) of JP-8 (R = 0.5 mm;
// sigma = 0.025 N/m) in a liquid of the same density (or, last, ten times lighter), periodic all
// round, both viscous enough that the start-up's capillary waves die within the run. The pressure
// inside exceeds the pressure outside by (d - 1) sigma / R (Laplace): measured on the mean
// pressure over r < R / 2 less the mean over r > 1.2 R, averaged over the last fifth of the run.
// The background pressure (2 sigma / R at equal densities) keeps the outer liquid's pressure
// positive.
// - 2D: R = 15 spacings in a square of side 4 R, viscosity 0.05 Pa s (Ohnesorge number 0.5),
//   10 ms (five capillary times sqrt(rho R^3 / sigma)); held to 4% (the curvature's own error is
//   1-3%, tests/sph/surface_tension_test.cpp). Measured (2026-11-30): +2.3%; +3.7% without the
//   background pressure (and at 25 spacings unstable without it, +2.6% with).
// - 3D: R = 8 spacings in a cube of side 2.5 R (8,000 particles), viscosity 0.1 Pa s (Ohnesorge
//   number 1), 6 ms (three capillary times). Measured (2026-11-30): -6.65% (-7.2% over 12 ms);
//   the deficit is the resolution's: -11.4% at R = 6 spacings, +0.35% at R = 10 (15,625
//   particles, 5 min on one core, too long for the suite). Held to 8%, set after that study.
// - 2D with the bath ten times lighter than the drop (its viscosity too, so that both have the
//   same kinematic viscosity), the same sound speed, the background pressure 20 sigma / R, 6 ms;
//   held to 4%. Measured (2026-12-02): +2.86% (+2.19% over 10 ms). With the background pressure
//   at 2 sigma / R the light bath's pressure stays near zero, its particles clump at the
//   interface (the tensile instability) and the jump reads +609%; with the bath's stiffness
//   rho0 c0^2 made the drop's (c0 times sqrt(10)) instead, -4.1%. At a density ratio of 100
//   (20 sigma / R, equal stiffness, 10 ms, 6 minutes on one core): +4.63%.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "particles/particle_store.hpp"
#include "sph/multi_material/multi_material_solver.hpp"

namespace partimix::sph {
namespace {

constexpr double kRadius = 5e-4;    // R [m]
constexpr double kSigma = 0.025;    // [N/m], JP-8
constexpr double kDensity = 800.0;  // [kg/m^3]

struct Setting {
  int dimensions;
  int radius_spacings;         // R / dp
  double box_side;             // in R
  double viscosity;            // [Pa s], the drop's; the bath's kinematic viscosity is the same
  double duration;             // [s]
  double density_ratio = 1.0;  // the drop's density over the bath's
  double background = 2.0;     // the background pressure, in sigma / R
};

MaterialSpec tait_liquid(const std::string& name, double viscosity) {
  MaterialSpec spec;
  spec.name = name;
  spec.eos.model = "tait";
  spec.eos.reference_density = kDensity;
  spec.eos.sound_speed = 2.5;  // ten times the capillary speed (sigma / (rho R))^(1/2)
  spec.specific_heat = 2000.0;
  spec.viscosity = viscosity;
  return spec;
}

// A lattice filling the periodic box, the points within R of its centre of material 0 (the drop),
// the others of the bath, `density_ratio` times lighter.
void lay_lattice(ParticleStore& store, const Domain& domain, double spacing, double density_ratio) {
  const int n = static_cast<int>(std::lround((domain.hi.x() - domain.lo.x()) / spacing));
  const int nz = domain.dimensions == 3 ? n : 1;
  const double cell = std::pow(spacing, domain.dimensions);
  std::vector<std::int32_t> material;
  for (int iz = 0; iz < nz; ++iz)
    for (int iy = 0; iy < n; ++iy)
      for (int ix = 0; ix < n; ++ix) {
        Vec3 x = domain.lo + spacing * Vec3(ix + 0.5, iy + 0.5, iz + 0.5);
        if (domain.dimensions == 2)
          x.z() = 0.0;
        const std::size_t i = store.size();
        store.resize(i + 1);
        store.position()[i] = x;
        store.id()[i] = static_cast<std::int64_t>(i);
        const bool drop = x.norm() < kRadius;
        store.mass()[i] = (drop ? kDensity : kDensity / density_ratio) * cell;
        material.push_back(drop ? 0 : 1);
      }
  store.add_integer("material", "").values = material;
}

// The mean pressure inside r < R / 2 less that outside r > 1.2 R.
double jump_now(const ParticleStore& store) {
  const std::vector<double>& pressure = store.find_scalar("pressure")->values;
  double inside = 0.0, outside = 0.0;
  int count_in = 0, count_out = 0;
  for (std::size_t i = 0; i < store.size(); ++i) {
    const double r = store.position()[i].norm();
    if (r < 0.5 * kRadius) {
      inside += pressure[i];
      ++count_in;
    } else if (r > 1.2 * kRadius) {
      outside += pressure[i];
      ++count_out;
    }
  }
  return inside / count_in - outside / count_out;
}

// The run's mean pressure jump over its last fifth.
double laplace_jump(const Setting& setting) {
  Domain domain;
  domain.dimensions = setting.dimensions;
  const double half = 0.5 * setting.box_side * kRadius;
  domain.lo = Vec3(-half, -half, setting.dimensions == 3 ? -half : 0.0);
  domain.hi = Vec3(half, half, setting.dimensions == 3 ? half : 0.0);
  domain.periodic = {true, true, setting.dimensions == 3};
  MaterialSpec drop = tait_liquid("drop", setting.viscosity);
  drop.surface_tension = kSigma;
  Config config;
  config.scheme = "multi_material";
  config.spacing = kRadius / setting.radius_spacings;
  MaterialSpec bath = tait_liquid("bath", setting.viscosity / setting.density_ratio);
  bath.eos.reference_density = kDensity / setting.density_ratio;
  config.multi_material.materials = {drop, bath};
  config.multi_material.background_pressure = setting.background * kSigma / kRadius;
  ParticleStore store;
  lay_lattice(store, domain, config.spacing, setting.density_ratio);
  MultiMaterialSolver solver(store, domain, config, Vec3::Zero());
  double jump_sum = 0.0;
  int samples = 0;
  while (solver.time() < setting.duration) {
    solver.step(solver.stable_dt());
    if (solver.time() < 0.8 * setting.duration)
      continue;
    jump_sum += jump_now(store);
    ++samples;
  }
  return jump_sum / samples;
}

void expect_laplace(const Setting& setting, double tolerance) {
  const double jump = laplace_jump(setting);
  const double expected = (setting.dimensions - 1) * kSigma / kRadius;
  std::printf("%dD Laplace jump %.4g Pa against %.4g Pa (%+.2f%%)\n", setting.dimensions, jump,
              expected, 100.0 * (jump / expected - 1.0));
  EXPECT_NEAR(jump, expected, tolerance * expected);
}

TEST(LaplaceDroplet, PressureJumpOfADiscIsSigmaOverRadius) {
  expect_laplace({2, 15, 4.0, 0.05, 0.01}, 0.04);
}

TEST(LaplaceDroplet, PressureJumpOfADiscHoldsWithABathTenTimesLighter) {
  expect_laplace({2, 15, 4.0, 0.05, 0.006, 10.0, 20.0}, 0.04);
}

TEST(LaplaceDroplet, PressureJumpOfASphereIsTwiceSigmaOverRadius) {
  expect_laplace({3, 8, 2.5, 0.1, 0.006}, 0.08);
}

}  // namespace
}  // namespace partimix::sph
