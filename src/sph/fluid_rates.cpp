#include "sph/fluid_rates.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "sph/pair_rates.hpp"

namespace partimix::sph {
namespace {

// Sizes the buffers (a no-op once sized) and sets 1 / rho of every particle.
void prepare(const Fields& f, RateBuffers& buffers, std::size_t fluid_count) {
  const auto all = static_cast<std::ptrdiff_t>(f.density.size());
  buffers.inverse_density.resize(f.density.size());
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t j = 0; j < all; ++j)
    buffers.inverse_density[j] = 1.0 / f.density[j];
  const auto threads = static_cast<std::size_t>(omp_get_max_threads());
  buffers.acceleration.resize(threads);
  buffers.density_rate.resize(threads);
  for (std::size_t t = 0; t < threads; ++t) {
    buffers.acceleration[t].resize(fluid_count);
    buffers.density_rate[t].resize(fluid_count);
  }
}

// Adds the terms of fluid particle i and its partners j > i to this thread's buffers.
void add_pairs_of(std::size_t i, const Fields& f, const NeighbourList& list,
                  const KernelTable& kernel, const Parameters& p, const double* inverse_density,
                  Vec3* acceleration, double* density_rate) {
  const PairCentre centre = pair_centre(i, f, p);
  const double m_i = f.mass[i];
  const double volume_i = m_i * inverse_density[i];
  Vec3 sum_acceleration = Vec3::Zero();
  double sum_density_rate = 0.0;
  auto fluid = [&](std::size_t j, const Vec3& r_ij, double r2) __attribute__((always_inline)) {
    const double inverse_density_j = inverse_density[j];
    const SharedPairTerms t =
        fluid_pair_terms(centre, j, r_ij, r2, inverse_density_j, f, kernel, p);
    const double m_j = f.mass[j];
    sum_acceleration += m_j * t.acceleration;
    sum_density_rate += m_j * t.density_rate + m_j * inverse_density_j * t.diffusion;
    acceleration[j] -= m_i * t.acceleration;
    density_rate[j] += m_i * t.density_rate - volume_i * t.diffusion;
  };
  auto wall = [&](std::size_t w, const Vec3& r_iw, double r2) __attribute__((always_inline)) {
    const PairRates rates = wall_pair_rates(centre, w, r_iw, r2, inverse_density[w], f, kernel, p);
    sum_acceleration += rates.acceleration;
    sum_density_rate += rates.density_rate;
  };
  list.for_each_partner(i, f.position, fluid, wall);
  acceleration[i] += sum_acceleration;
  density_rate[i] += sum_density_rate;
}

}  // namespace

RateExtremes compute_fluid_rates(Fields& f, std::size_t fluid_count, const NeighbourList& list,
                                 const KernelTable& kernel, const Parameters& p,
                                 RateBuffers& buffers) {
  prepare(f, buffers, fluid_count);
  const auto n = static_cast<std::ptrdiff_t>(fluid_count);
  double max_acceleration2 = 0.0;
  double max_speed2 = 0.0;
#pragma omp parallel reduction(max : max_acceleration2, max_speed2)
  {
    const auto thread = static_cast<std::size_t>(omp_get_thread_num());
    Vec3* acceleration = buffers.acceleration[thread].data();
    double* density_rate = buffers.density_rate[thread].data();
    std::fill_n(acceleration, fluid_count, Vec3::Zero());
    std::fill_n(density_rate, fluid_count, 0.0);
#pragma omp barrier
    // A fixed assignment of particles to threads, so that a run is repeatable.
#pragma omp for schedule(static, 256)
    for (std::ptrdiff_t ii = 0; ii < n; ++ii)
      add_pairs_of(static_cast<std::size_t>(ii), f, list, kernel, p, buffers.inverse_density.data(),
                   acceleration, density_rate);
    const auto threads = static_cast<std::size_t>(omp_get_num_threads());
#pragma omp for schedule(static)
    for (std::ptrdiff_t ii = 0; ii < n; ++ii) {
      const auto i = static_cast<std::size_t>(ii);
      Vec3 a = buffers.acceleration[0][i];
      double rate = buffers.density_rate[0][i];
      for (std::size_t t = 1; t < threads; ++t) {
        a += buffers.acceleration[t][i];
        rate += buffers.density_rate[t][i];
      }
      f.density_rate[i] = rate;
      f.acceleration[i] = a + p.gravity;
      max_acceleration2 = std::max(max_acceleration2, f.acceleration[i].squaredNorm());
      max_speed2 = std::max(max_speed2, f.velocity[i].squaredNorm());
    }
  }
  return {std::sqrt(max_acceleration2), std::sqrt(max_speed2)};
}

}  // namespace partimix::sph
