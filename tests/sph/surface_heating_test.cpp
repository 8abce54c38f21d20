// Heat through the surfaces of a material's bodies (sph/multi_material/surface_heating.hpp;
// docs/multi-material-sph.md, "The scheme"): on a unit lattice (h = 1.5, every volume 1), gas
// discs of radii 6 and 4 whose nearest particles are 8 apart in a liquid box are two bodies;
// each particle of a disc of N particles takes q'' 2 (pi N)^(1/2) / N, so that each disc takes in
// q'' times the perimeter of the disc of its area, the smaller more per volume; the liquid takes
// nothing. Discs 1 apart (closer than h) are one body. A fragment of fewer than 10 particles (a
// disc of radius 1.5: 9) takes nothing. A 3D ball of N particles takes
// q'' (36 pi N^2)^(1/3) in all. In the solver, two blocks of such a material at rest in a liquid
// (every pressure at the ambient, no conduction) heat at dT/dt = q'' S / (V rho c_v), each its
// own, and the liquid not at all. Tolerance 1e-12: round-off.
#include "sph/multi_material/surface_heating.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>
#include <vector>

#include "particles/cell_grid.hpp"
#include "particles/domain.hpp"
#include "particles/particle_store.hpp"
#include "sph/multi_material/multi_material_solver.hpp"
#include "support/multi_material_setup.hpp"

namespace partimix::sph {
namespace {

constexpr double kTight = 1e-12;
constexpr int kLiquid = 0;
constexpr int kGas = 1;
constexpr double kFlux = 2.0e7;  // q'' [W/m^2]
constexpr double kH = 1.5;

struct Lattice {
  std::vector<Vec3> position;
  std::vector<std::int32_t> material;
  std::vector<int> body;  // which sphere or disc, -1 for the liquid
};

struct Ball {
  Vec3 centre;
  double radius;
};

// A unit lattice filling [0, nx) x [0, ny) x [0, nz), gas within the balls.
Lattice lattice(int nx, int ny, int nz, const std::vector<Ball>& balls) {
  Lattice out;
  for (int z = 0; z < nz; ++z) {
    for (int y = 0; y < ny; ++y) {
      for (int x = 0; x < nx; ++x) {
        const Vec3 point(x, y, z);
        int body = -1;
        for (std::size_t k = 0; k < balls.size(); ++k) {
          if ((point - balls[k].centre).norm() <= balls[k].radius)
            body = static_cast<int>(k);
        }
        out.position.push_back(point);
        out.material.push_back(body < 0 ? kLiquid : kGas);
        out.body.push_back(body);
      }
    }
  }
  return out;
}

// The source of every particle of `lattice`, in a domain of `dimensions` round it.
std::vector<double> sources(const Lattice& lattice, int dimensions, const Vec3& hi) {
  Domain domain;
  domain.dimensions = dimensions;
  domain.lo = Vec3::Constant(-1.0);
  domain.hi = hi;
  if (dimensions == 2) {
    domain.lo.z() = 0.0;
    domain.hi.z() = 1.0;
  }
  CellGrid grid(domain, 2.0 * kH);
  grid.build(lattice.position);
  const std::size_t n = lattice.position.size();
  const std::vector<double> h(n, kH);
  const std::vector<double> unit(n, 1.0);
  SurfaceHeating heating({0.0, kFlux}, dimensions);
  std::vector<double> source(n, -1.0);
  heating.update({lattice.position, h, unit, unit, lattice.material}, n, grid, source);
  return source;
}

int count(const Lattice& lattice, int body) {
  return static_cast<int>(std::ranges::count(lattice.body, body));
}

TEST(SurfaceHeating, EachDiscTakesInThePerimeterOfItsArea) {
  const Lattice discs = lattice(40, 24, 1, {{{10, 12, 0}, 6.0}, {{28, 12, 0}, 4.0}});
  const std::vector<double> source = sources(discs, 2, {41.0, 25.0, 1.0});
  for (int body = 0; body < 2; ++body) {
    const double n = count(discs, body);
    const double expected = kFlux * 2.0 * std::sqrt(std::numbers::pi * n) / n;
    double power = 0.0;
    for (std::size_t i = 0; i < source.size(); ++i) {
      if (discs.body[i] == body) {
        EXPECT_NEAR(source[i], expected, kTight * expected);
        power += source[i];
      }
    }
    EXPECT_NEAR(power, kFlux * 2.0 * std::sqrt(std::numbers::pi * n), kTight * power);
  }
  EXPECT_GT(source[static_cast<std::size_t>(12 * 40 + 28)],
            1.4 * source[static_cast<std::size_t>(12 * 40 + 10)]);
  for (std::size_t i = 0; i < source.size(); ++i) {
    if (discs.body[i] < 0) {
      EXPECT_EQ(source[i], 0.0);
    }
  }
}

TEST(SurfaceHeating, DiscsCloserThanTheSmoothingLengthAreOneBody) {
  // Radii 6 and 4 about x = 10 and 22: the nearest gas particles, at x = 16 and 18 on y = 12,
  // are 2 apart, beyond h = 1.5; with the second disc about x = 21 they are 1 apart.
  const Lattice apart = lattice(40, 24, 1, {{{10, 12, 0}, 6.0}, {{22, 12, 0}, 4.0}});
  const Lattice touching = lattice(40, 24, 1, {{{10, 12, 0}, 6.0}, {{21, 12, 0}, 4.0}});
  const std::vector<double> two = sources(apart, 2, {41.0, 25.0, 1.0});
  const std::vector<double> one = sources(touching, 2, {41.0, 25.0, 1.0});
  const double n = count(touching, 0) + count(touching, 1);
  const double joined = kFlux * 2.0 * std::sqrt(std::numbers::pi * n) / n;
  const std::size_t centre = 12 * 40 + 10;
  EXPECT_NEAR(one[centre], joined, kTight * joined);
  const double alone =
      kFlux * 2.0 * std::sqrt(std::numbers::pi * count(apart, 0)) / count(apart, 0);
  EXPECT_NEAR(two[centre], alone, kTight * alone);
}

TEST(SurfaceHeating, AFragmentTakesNothing) {
  const Lattice discs = lattice(40, 24, 1, {{{10, 12, 0}, 6.0}, {{28, 12, 0}, 1.5}});
  ASSERT_EQ(count(discs, 1), 9);
  const std::vector<double> source = sources(discs, 2, {41.0, 25.0, 1.0});
  for (std::size_t i = 0; i < source.size(); ++i) {
    if (discs.body[i] == 1) {
      EXPECT_EQ(source[i], 0.0);
    }
  }
  const double n = count(discs, 0);
  const double expected = kFlux * 2.0 * std::sqrt(std::numbers::pi * n) / n;
  EXPECT_NEAR(source[static_cast<std::size_t>(12 * 40 + 10)], expected, kTight * expected);
}

TEST(SurfaceHeating, ABallTakesInTheSurfaceOfTheSphereOfItsVolume) {
  const Lattice ball = lattice(14, 14, 14, {{{7, 7, 7}, 4.0}});
  const std::vector<double> source = sources(ball, 3, {15.0, 15.0, 15.0});
  const double n = count(ball, 0);
  const double surface = std::cbrt(36.0 * std::numbers::pi * n * n);
  double power = 0.0;
  for (std::size_t i = 0; i < source.size(); ++i) {
    power += source[i];
    if (ball.body[i] < 0) {
      EXPECT_EQ(source[i], 0.0);
    }
  }
  EXPECT_NEAR(power, kFlux * surface, kTight * power);
}

MaterialSpec tait_fluid(const std::string& name, double surface_heat_flux) {
  MaterialSpec spec;
  spec.name = name;
  spec.eos.model = "tait";
  spec.eos.reference_density = 800.0;
  spec.eos.sound_speed = 50.0;
  spec.specific_heat = 2000.0;
  spec.surface_heat_flux = surface_heat_flux;
  return spec;
}

TEST(SurfaceHeating, TheSolverHeatsEachBlockByItsOwnShare) {
  constexpr double kSpacing = 1e-3;
  const Domain domain = test_support::plane_domain(-0.01, -0.01, 0.04, 0.03);
  const Config config = test_support::multi_material_config(
      kSpacing, {tait_fluid("liquid", 0.0), tait_fluid("gas", kFlux)});
  ParticleStore store;
  std::vector<int> block;  // 0 for x < 10, 1 beyond, -1 liquid
  for (int j = 0; j < 12; ++j) {
    for (int i = 0; i < 30; ++i) {
      const std::size_t n = store.size();
      store.resize(n + 1);
      store.position()[n] = Vec3(i + 0.5, j + 0.5, 0.0) * kSpacing;
      store.mass()[n] = 800.0 * kSpacing * kSpacing;
      store.id()[n] = static_cast<std::int64_t>(n);
      const bool inside = j >= 3 && j < 9 && ((i >= 3 && i < 9) || (i >= 18 && i < 22));
      block.push_back(inside ? (i < 10 ? 0 : 1) : -1);
    }
  }
  Field<std::int32_t>& material = store.add_integer("material", "");
  for (std::size_t i = 0; i < store.size(); ++i)
    material.values[i] = block[i] < 0 ? kLiquid : kGas;
  const MultiMaterialSolver solver(store, domain, config, Vec3::Zero());
  const std::vector<double>& rate = store.find_scalar("temperature_rate")->values;
  for (std::size_t i = 0; i < store.size(); ++i) {
    if (block[i] < 0) {
      EXPECT_EQ(rate[i], 0.0) << i;
      continue;
    }
    const double volume = (block[i] == 0 ? 36.0 : 24.0) * kSpacing * kSpacing;
    const double expected =
        kFlux * 2.0 * std::sqrt(std::numbers::pi * volume) / (volume * 800.0 * 2000.0);
    EXPECT_NEAR(rate[i], expected, kTight * expected) << i;
  }
}

}  // namespace
}  // namespace partimix::sph
