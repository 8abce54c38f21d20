// The fluid rates, each fluid pair computed once over the half neighbour list and given to both
// particles, equal the direct sum over every neighbour of the terms of docs/sph.md ("Discrete
// equations"), written out here pair by pair, on a disordered block of fluid over two wall
// layers with random velocities, pressures, densities, viscosities and viscous stresses: with
// each viscous operator, artificial viscosity and Fourtakas diffusion, on one and two threads
// (within 1e-12 of the largest rate: round-off); and with variable smoothing lengths (h_i within
// 15% of h), the pair's mean kernel gradient and mean h, a wall's with the fluid particle's h
// (docs/sph.md, "Variable smoothing length"). The stress form's term alone is also the explicit
// part of the semi-implicit viscous step.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "particles/cell_grid.hpp"
#include "sph/fluid_rates.hpp"
#include "sph/kernel.hpp"
#include "sph/viscous_stress.hpp"

namespace partimix::sph {
namespace {

constexpr double kSpacing = 0.01;

struct Block {
  ParticleStore store;
  Fields fields{store};
  Parameters p;
  Domain domain;
  std::size_t fluid_count = 0;

  explicit Block(ViscousOperator viscous_operator) {
    domain.lo = Vec3(-0.05, -0.05, -0.05);
    domain.hi = Vec3(0.15, 0.15, 0.15);
    p.spacing = kSpacing;
    p.h = 1.7 * kSpacing;
    p.eta2 = 0.01 * p.h * p.h;
    p.reference_density = 1000.0;
    p.sound_speed = 15.0;
    p.gravity = Vec3(0.0, 0.0, -9.81);
    p.hydrostatic_gravity = p.gravity;
    p.viscous_operator = viscous_operator;
    p.artificial_viscosity = 0.05;
    p.diffusion = DensityDiffusion::fourtakas;
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::vector<Vec3> fluid;
    std::vector<Vec3> wall;
    for (int i = 0; i < 8; ++i)
      for (int j = 0; j < 8; ++j)
        for (int k = -2; k < 8; ++k) {
          const Vec3 lattice = kSpacing * Vec3(i + 0.5, j + 0.5, k + 0.5);
          (k < 0 ? wall : fluid)
              .push_back(k < 0 ? lattice
                               : Vec3(lattice + 0.2 * kSpacing * Vec3(u(rng), u(rng), u(rng))));
        }
    fluid_count = fluid.size();
    store.resize(fluid.size() + wall.size());
    if (viscous_operator == ViscousOperator::stress)
      fields.viscous_stress.resize(store.size());
    for (std::size_t n = 0; n < store.size(); ++n) {
      const bool is_fluid_particle = n < fluid_count;
      fields.kind[n] =
          static_cast<std::int32_t>(is_fluid_particle ? ParticleKind::fluid : ParticleKind::wall);
      fields.position[n] = is_fluid_particle ? fluid[n] : wall[n - fluid_count];
      fields.mass[n] = 1000.0 * std::pow(kSpacing, 3) * (1.0 + 0.1 * u(rng));
      fields.velocity[n] = 0.3 * Vec3(u(rng), u(rng), u(rng));
      fields.wall_velocity[n] = 0.3 * Vec3(u(rng), u(rng), u(rng));
      fields.density[n] = 1000.0 * (1.0 + 0.02 * u(rng));
      fields.pressure[n] = 500.0 * (1.0 + u(rng));
      fields.viscosity[n] = 0.5 * (1.5 + u(rng));
      if (viscous_operator == ViscousOperator::stress)
        fields.viscous_stress[n] = Mat3::Random();
    }
  }

  // Each fluid particle's h_i = h / s_i, s_i within 15% of 1, as the solver sets them.
  void vary_smoothing_lengths() {
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    fields.kernel_scale.assign(store.size(), 1.0);
    fields.gradient_scale.assign(store.size(), 1.0);
    for (std::size_t n = 0; n < fluid_count; ++n) {
      fields.kernel_scale[n] = 1.0 + 0.15 * u(rng);
      fields.gradient_scale[n] = std::pow(fields.kernel_scale[n], 4);
    }
  }

  // dW/dr of particle n's kernel: W(r, h_n) = s^3 W(r s, h), s = h / h_n.
  double derivative_of(std::size_t n, double r, const KernelTable& kernel) const {
    if (fields.kernel_scale.empty())
      return kernel.derivative(r);
    const double s = fields.kernel_scale[n];
    return std::pow(s, 4) * kernel.derivative(r * s);
  }

  double smoothing_length_of(std::size_t n) const {
    return fields.kernel_scale.empty() ? p.h : p.h / fields.kernel_scale[n];
  }

  // docs/sph.md, term by term, summed over all neighbours j of fluid particle i.
  void reference(const KernelTable& kernel, std::vector<Vec3>& acceleration,
                 std::vector<double>& density_rate) const {
    const Fields& f = fields;
    for (std::size_t i = 0; i < fluid_count; ++i) {
      Vec3 a = p.gravity;
      double rate = 0.0;
      const double rho_i = f.density[i];
      for (std::size_t j = 0; j < store.size(); ++j) {
        const Vec3 r_ij = f.position[i] - f.position[j];
        const double r2 = r_ij.squaredNorm();
        if (j == i)
          continue;
        const double r = std::sqrt(r2);
        const bool fluid_j = j < fluid_count;
        const double dw_dr = fluid_j
                                 ? 0.5 * (derivative_of(i, r, kernel) + derivative_of(j, r, kernel))
                                 : derivative_of(i, r, kernel);
        const double h_pair = fluid_j ? 0.5 * (smoothing_length_of(i) + smoothing_length_of(j))
                                      : smoothing_length_of(i);
        if (dw_dr == 0.0)
          continue;
        const Vec3 grad = dw_dr / r * r_ij;
        const double rho_j = f.density[j];
        const double m_j = f.mass[j];
        const Vec3 v_ij = f.velocity[i] - f.velocity[j];
        const Vec3 v_viscous = fluid_j ? v_ij : Vec3(f.velocity[i] - f.wall_velocity[j]);
        rate += m_j * v_ij.dot(grad);
        a -= m_j * (f.pressure[i] / (rho_i * rho_i) + f.pressure[j] / (rho_j * rho_j)) * grad;
        const double eta_j = fluid_j ? f.viscosity[j] : f.viscosity[i];
        a += m_j * (f.viscosity[i] + eta_j) * r_ij.dot(grad) / (rho_i * rho_j * (r2 + p.eta2)) *
             v_viscous;
        if (p.viscous_operator == ViscousOperator::stress) {
          a += m_j *
               (f.viscous_stress[i] / (rho_i * rho_i) + f.viscous_stress[j] / (rho_j * rho_j)) *
               grad;
        }
        if (v_viscous.dot(r_ij) < 0.0) {
          const double mu = h_pair * v_viscous.dot(r_ij) / (r2 + p.eta2);
          const double pi = -p.artificial_viscosity * p.sound_speed * mu / (0.5 * (rho_i + rho_j));
          a -= m_j * pi * grad;
        }
        if (fluid_j) {
          const double difference =
              rho_j - rho_i +
              p.reference_density * p.gravity.dot(r_ij) / std::pow(p.sound_speed, 2);
          rate += 2.0 * p.delta * h_pair * p.sound_speed * difference * (-r_ij.dot(grad) / r2) *
                  m_j / rho_j;
        }
      }
      acceleration[i] = a;
      density_rate[i] = rate;
    }
  }
};

void expect_reference(ViscousOperator viscous_operator, int threads, bool variable_h = false) {
  Block block(viscous_operator);
  if (variable_h)
    block.vary_smoothing_lengths();
  const auto kernel = kernel_registry().create("wendland_c2");
  const KernelTable table(*kernel, block.p.h, 3);
  std::vector<Vec3> acceleration(block.fluid_count);
  std::vector<double> density_rate(block.fluid_count);
  block.reference(table, acceleration, density_rate);
  // The largest h_i is below h / 0.85: the list reaches 1.25 supports.
  NeighbourList list(block.domain, 1.25 * table.support_radius(), 0.1 * table.support_radius());
  list.update(block.fields.position, block.fluid_count, block.fluid_count);
  RateBuffers buffers;
  omp_set_num_threads(threads);
  compute_fluid_rates(block.fields, block.fluid_count, list, table, block.p, buffers);
  omp_set_num_threads(1);
  double largest_a = 0.0;
  double largest_rate = 0.0;
  for (std::size_t i = 0; i < block.fluid_count; ++i) {
    largest_a = std::max(largest_a, acceleration[i].norm());
    largest_rate = std::max(largest_rate, std::abs(density_rate[i]));
  }
  for (std::size_t i = 0; i < block.fluid_count; ++i) {
    EXPECT_LT((block.fields.acceleration[i] - acceleration[i]).norm(), 1e-12 * largest_a) << i;
    EXPECT_NEAR(block.fields.density_rate[i], density_rate[i], 1e-12 * largest_rate) << i;
  }
}

TEST(FluidRates, MorrisEqualsTheDirectSumOnOneThread) {
  expect_reference(ViscousOperator::morris, 1);
}
TEST(FluidRates, MorrisEqualsTheDirectSumOnTwoThreads) {
  expect_reference(ViscousOperator::morris, 2);
}
TEST(FluidRates, StressFormEqualsTheDirectSumOnTwoThreads) {
  expect_reference(ViscousOperator::stress, 2);
}
TEST(FluidRates, VariableSmoothingLengthsEqualTheDirectSumOnTwoThreads) {
  expect_reference(ViscousOperator::morris, 2, true);
}

// The explicit part of the semi-implicit viscous step (docs/sph.md, "Implicit viscosity") is the
// stress form's pair term alone: the direct sum with every other term switched off.
TEST(FluidRates, StressDivergenceIsTheStressFormsPairTerm) {
  Block block(ViscousOperator::stress);
  block.p.gravity = Vec3::Zero();
  block.p.artificial_viscosity = 0.0;
  std::fill(block.fields.pressure.begin(), block.fields.pressure.end(), 0.0);
  std::fill(block.fields.viscosity.begin(), block.fields.viscosity.end(), 0.0);
  const auto kernel = kernel_registry().create("wendland_c2");
  const KernelTable table(*kernel, block.p.h, 3);
  std::vector<Vec3> expected(block.fluid_count);
  std::vector<double> density_rate(block.fluid_count);
  block.reference(table, expected, density_rate);
  CellGrid grid(block.domain, table.support_radius());
  grid.build(block.fields.position);
  std::vector<Vec3> divergence;
  omp_set_num_threads(2);
  compute_stress_divergence(block.fields, block.fluid_count, grid, table, divergence);
  omp_set_num_threads(1);
  double largest = 0.0;
  for (const Vec3& a : expected)
    largest = std::max(largest, a.norm());
  ASSERT_GT(largest, 0.0);
  for (std::size_t i = 0; i < block.fluid_count; ++i)
    EXPECT_LT((divergence[i] - expected[i]).norm(), 1e-12 * largest) << i;
}

}  // namespace
}  // namespace partimix::sph
