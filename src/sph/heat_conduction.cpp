#include "sph/heat_conduction.hpp"

#include <algorithm>
#include <cmath>

namespace partimix::sph {

namespace {

// 0.01 h^2 keeps the pair term finite as r_ij -> 0 (Cleary & Monaghan 1999).
constexpr double kSoftening = 0.01;

// The pair's conductivity factor 4 k_i k_j / (k_i + k_j), twice the harmonic mean; 0 between
// two insulators.
double pair_conductivity(double ki, double kj) {
  const double sum = ki + kj;
  return sum > 0.0 ? 4.0 * ki * kj / sum : 0.0;
}

}  // namespace

void add_conduction_rates(const ThermalParticles& p, std::size_t count, const CellGrid& grid,
                          const ScaledKernel& kernel, std::span<double> energy_rate) {
  const double support = kernel.support();
  const auto n = static_cast<std::ptrdiff_t>(count);
#pragma omp parallel for schedule(dynamic, 512)
  for (std::ptrdiff_t ii = 0; ii < n; ++ii) {
    const auto i = static_cast<std::size_t>(ii);
    double rate = 0.0;
    grid.for_each_neighbour(
        i, p.position,
        [&](std::size_t j, const Vec3&, double r2) {
          const double reach = support * std::max(p.h[i], p.h[j]);
          if (j == i || r2 >= reach * reach)
            return;
          const double r = std::sqrt(r2);
          const double h = 0.5 * (p.h[i] + p.h[j]);
          // r_ij . grad_i W_ij = r dW/dr.
          const double slope = 0.5 * (kernel.derivative(r, p.h[i]) + kernel.derivative(r, p.h[j]));
          const double flux = r * slope / (r2 + kSoftening * h * h);
          rate += p.mass[j] / (p.density[i] * p.density[j]) *
                  pair_conductivity(p.conductivity[i], p.conductivity[j]) *
                  (p.temperature[i] - p.temperature[j]) * flux;
        },
        count);
    energy_rate[i] += rate;
  }
}

}  // namespace partimix::sph
