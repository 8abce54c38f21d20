#include "sph/shepard_filter.hpp"

#include <cmath>
#include <cstddef>

namespace partimix::sph {

void apply_shepard_filter(Fields& f, const CellGrid& grid, const KernelTable& kernel,
                          std::vector<double>& scratch) {
  const auto n = static_cast<std::ptrdiff_t>(f.position.size());
  scratch.resize(f.position.size());
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t ii = 0; ii < n; ++ii) {
    const auto i = static_cast<std::size_t>(ii);
    scratch[i] = f.density[i];
    if (!is_fluid(f.kind[i]))
      continue;
    double mass_sum = 0.0;
    double volume_sum = 0.0;
    grid.for_each_neighbour(i, f.position, [&](std::size_t j, const Vec3&, double r2) {
      const double W = kernel.value(std::sqrt(r2));
      mass_sum += f.mass[j] * W;
      volume_sum += f.mass[j] / f.density[j] * W;
    });
    scratch[i] = mass_sum / volume_sum;
  }
  f.density.swap(scratch);
}

}  // namespace partimix::sph
