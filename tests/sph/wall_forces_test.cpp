// The loads on a solid body (sph/wall_forces.hpp; docs/power.md, "Uniform parts of the load"),
// 2D: a rectangle 6 x 12 spacings, its particles on a lattice turned by 30 degrees, in a fluid
// on the lattice points outside it, each moved off its point by up to 0.3 dp at random,
// h = 1.5 dp.
// - A uniform pressure exerts no force and no torque on the body, whatever the fluid's
//   arrangement: the part of the load it gives is taken from the body's own particles, whose
//   pairs cancel. Asserted to round-off (1e-12 of p times the perimeter). The pair sums alone
//   (the loads of a container wall) give 13.5% of p times the long side here: the test can fail.
// - A linear pressure p = p0 + G . x (at the wall particles too, as the wall extrapolation gives
//   a hydrostatic one) exerts the force -(integral of grad p over the body) = -G A and no torque
//   about the centre. Asserted within 3% of |G| A (measured 2.0%; the pair sums alone 35%, and
//   25% with the body's lattice aligned with the fluid's, against 0.4%), the torque within 1% of
//   |G| A L.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "particles/cell_grid.hpp"
#include "sph/kernel.hpp"
#include "sph/kernel_table.hpp"
#include "sph/wall_forces.hpp"

namespace partimix::sph {
namespace {

constexpr double kSpacing = 0.01;
constexpr double kDensity = 1000.0;
constexpr double kWidth = 0.06;
constexpr double kHeight = 0.12;
const Vec3 kCentre(0.03, 0.06, 0.0);

struct Immersed {
  ParticleStore store;
  std::size_t fluid_count = 0;
  Domain domain;
  Parameters p;
};

// Whether x lies inside the body turned by `angle` about its centre.
bool inside_body(const Vec3& x, double angle) {
  const Vec3 d = x - kCentre;
  const double u = std::cos(angle) * d.x() + std::sin(angle) * d.y();
  const double v = -std::sin(angle) * d.x() + std::cos(angle) * d.y();
  return std::abs(u) < 0.5 * kWidth && std::abs(v) < 0.5 * kHeight;
}

void immerse(Immersed& m, double jitter, std::int32_t solid) {
  m.domain.dimensions = 2;
  m.domain.lo = Vec3(-0.1, -0.1, 0.0);
  m.domain.hi = Vec3(0.16, 0.22, 0.0);
  const double angle = std::numbers::pi / 6.0;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-jitter, jitter);
  std::vector<Vec3> fluid;
  for (int i = -8; i < 14; ++i)
    for (int j = -8; j < 20; ++j) {
      const Vec3 x = kSpacing * Vec3(i + 0.5, j + 0.5, 0.0);
      if (!inside_body(x, angle))
        fluid.push_back(x + kSpacing * Vec3(u(rng), u(rng), 0.0));
    }
  std::vector<Vec3> body;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 12; ++j) {
      const Vec3 d = kSpacing * Vec3(i + 0.5, j + 0.5, 0.0) - kCentre;
      body.push_back(kCentre + Vec3(std::cos(angle) * d.x() - std::sin(angle) * d.y(),
                                    std::sin(angle) * d.x() + std::cos(angle) * d.y(), 0.0));
    }
  m.fluid_count = fluid.size();
  m.store.resize(fluid.size() + body.size());
  auto& body_of = m.store.add_integer("body", "").values;
  auto& solid_of = m.store.add_integer("solid", "").values;
  for (std::size_t n = 0; n < m.store.size(); ++n) {
    const bool is_fluid_particle = n < m.fluid_count;
    m.store.kind()[n] =
        static_cast<std::int32_t>(is_fluid_particle ? ParticleKind::fluid : ParticleKind::wall);
    m.store.position()[n] = is_fluid_particle ? fluid[n] : body[n - m.fluid_count];
    m.store.mass()[n] = kDensity * kSpacing * kSpacing;
    body_of[n] = is_fluid_particle ? -1 : 0;
    solid_of[n] = is_fluid_particle ? 0 : solid;
  }
  m.p.dimensions = 2;
  m.p.spacing = kSpacing;
  m.p.h = 1.5 * kSpacing;
  m.p.eta2 = 0.01 * m.p.h * m.p.h;
  m.p.reference_density = kDensity;
  m.p.sound_speed = 10.0;
}

struct Load {
  Vec3 force = Vec3::Zero();
  double torque = 0.0;  // about the body's centre
};

// The load on the body with the pressure p(x) = p0 + gradient . x at every particle.
Load load_under(Immersed& m, double p0, const Vec3& gradient) {
  Fields f(m.store);
  for (std::size_t n = 0; n < m.store.size(); ++n) {
    f.density[n] = kDensity;
    f.pressure[n] = p0 + gradient.dot(f.position[n]);
    f.viscosity[n] = 1.0;
  }
  const auto kernel = kernel_registry().create("wendland_c2");
  const KernelTable table(*kernel, m.p.h, 2);
  CellGrid grid(m.domain, table.support_radius());
  grid.build(f.position);
  std::vector<Vec3> force(m.store.size());
  std::vector<Vec3> couple(m.store.size());
  compute_wall_forces(f, m.fluid_count, grid, table, m.p, WallTraction::dynamics, {force, couple});
  Load load;
  for (std::size_t w = m.fluid_count; w < m.store.size(); ++w) {
    load.force += force[w];
    load.torque += ((f.position[w] - kCentre).cross(force[w]) + couple[w]).z();
  }
  return load;
}

TEST(WallForces, AUniformPressureExertsNoLoadOnASolidBodyInADisorderedFluid) {
  const double pressure = 2000.0;
  Immersed solid;
  immerse(solid, 0.3, 1);
  const Load load = load_under(solid, pressure, Vec3::Zero());
  const double scale = pressure * 2.0 * (kWidth + kHeight);
  EXPECT_LT(load.force.norm(), 1e-12 * scale);
  EXPECT_LT(std::abs(load.torque), 1e-12 * scale * kHeight);
  Immersed pairs_only;
  immerse(pairs_only, 0.3, 0);
  const Load pair_load = load_under(pairs_only, pressure, Vec3::Zero());
  std::printf("uniform pressure, pair sums alone: force %.4f of p times the long side\n",
              pair_load.force.norm() / (pressure * kHeight));
  EXPECT_GT(pair_load.force.norm(), 0.01 * pressure * kHeight);
}

TEST(WallForces, ALinearPressureGivesTheForceOfItsGradientOverTheBody) {
  const Vec3 gradient(3000.0, -5000.0, 0.0);
  Immersed solid;
  immerse(solid, 0.3, 1);
  const Load load = load_under(solid, 1000.0, gradient);
  const double area = kWidth * kHeight;
  const Vec3 exact = -gradient * area;
  std::printf("linear pressure: force error %.4f, torque %.2e of |G| A L\n",
              (load.force - exact).norm() / exact.norm(), load.torque / (exact.norm() * kHeight));
  EXPECT_LT((load.force - exact).norm(), 0.03 * exact.norm());
  EXPECT_LT(std::abs(load.torque), 0.01 * exact.norm() * kHeight);
}

}  // namespace
}  // namespace partimix::sph
