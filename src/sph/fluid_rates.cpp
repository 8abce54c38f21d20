#include "sph/fluid_rates.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "sph/pair_rates.hpp"

namespace partimix::sph {
namespace {

// The sum over the neighbours of fluid particle i.
PairRates rates_of(std::size_t i, const Fields& f, const CellGrid& grid, const KernelTable& kernel,
                   const Parameters& p) {
  const PairCentre centre = pair_centre(i, f, p);
  PairRates sum;
  grid.for_each_neighbour(i, f.position, [&](std::size_t j, const Vec3& r_ij, double r2) {
    if (j == i)
      return;
    const PairRates pair = pair_rates(centre, j, r_ij, r2, f, kernel, p);
    sum.density_rate += pair.density_rate;
    sum.acceleration += pair.acceleration;
  });
  return sum;
}

}  // namespace

RateExtremes compute_fluid_rates(Fields& f, std::size_t fluid_count, const CellGrid& grid,
                                 const KernelTable& kernel, const Parameters& p) {
  const auto n = static_cast<std::ptrdiff_t>(fluid_count);
  double max_acceleration2 = 0.0;
  double max_speed2 = 0.0;
#pragma omp parallel for schedule(dynamic, 512) reduction(max : max_acceleration2, max_speed2)
  for (std::ptrdiff_t ii = 0; ii < n; ++ii) {
    const auto i = static_cast<std::size_t>(ii);
    const PairRates rates = rates_of(i, f, grid, kernel, p);
    f.density_rate[i] = rates.density_rate;
    f.acceleration[i] = rates.acceleration + p.gravity;
    max_acceleration2 = std::max(max_acceleration2, f.acceleration[i].squaredNorm());
    max_speed2 = std::max(max_speed2, f.velocity[i].squaredNorm());
  }
  return {std::sqrt(max_acceleration2), std::sqrt(max_speed2)};
}

}  // namespace partimix::sph
