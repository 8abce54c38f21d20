#include "sph/dirichlet_temperature.hpp"

#include <cmath>

namespace partimix::sph {

void dirichlet_temperatures(const DirichletParticles& p, std::size_t count, const CellGrid& grid,
                            const ScaledKernel& kernel, std::span<double> conducted) {
  const auto n = static_cast<std::ptrdiff_t>(count);
#pragma omp parallel for schedule(dynamic, 512)
  for (std::ptrdiff_t gg = 0; gg < n; ++gg) {
    const auto g = static_cast<std::size_t>(gg);
    conducted[g] = p.temperature[g];
    if (p.held[g] == 0)
      continue;
    double weight = 0.0;
    double weighted = 0.0;
    grid.for_each_neighbour(
        g, p.position,
        [&](std::size_t f, const Vec3&, double r2) {
          if (p.held[f] != 0)
            return;
          const double w = kernel.value(std::sqrt(r2), p.h[g]);
          weight += w;
          weighted += w * p.temperature[f];
        },
        count);
    if (weight > 0.0)
      conducted[g] = 2.0 * p.temperature[g] - weighted / weight;
  }
}

}  // namespace partimix::sph
