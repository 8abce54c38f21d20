#include "sph/shear_rate.hpp"

#include <cstddef>

#include "sph/velocity_gradient.hpp"

namespace partimix::sph {

void compute_shear_rates(Fields& f, std::size_t fluid_count, const CellGrid& grid,
                         const KernelTable& kernel, int dimensions, bool corrected) {
  const auto n = static_cast<std::ptrdiff_t>(fluid_count);
#pragma omp parallel for schedule(dynamic, 512)
  for (std::ptrdiff_t ii = 0; ii < n; ++ii) {
    const auto i = static_cast<std::size_t>(ii);
    const Mat3 gradient = velocity_gradient(i, f, grid, kernel, dimensions, corrected);
    f.shear_rate[i] = shear_rate_of(0.5 * (gradient + gradient.transpose()));
  }
}

}  // namespace partimix::sph
