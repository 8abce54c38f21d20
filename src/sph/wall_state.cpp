#include "sph/wall_state.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace partimix::sph {

void update_wall_state(Fields& f, std::size_t fluid_count, const CellGrid& grid,
                       const KernelTable& kernel, const EquationOfState& eos,
                       const Parameters& parameters) {
  const auto first = static_cast<std::ptrdiff_t>(fluid_count);
  const auto n = static_cast<std::ptrdiff_t>(f.position.size());
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t ii = first; ii < n; ++ii) {
    const auto w = static_cast<std::size_t>(ii);
    double weight = 0.0;
    double pressure = 0.0;
    Vec3 density_moment = Vec3::Zero();
    Vec3 velocity = Vec3::Zero();
    auto gather = [&](std::size_t j, const Vec3& r_wj, double r2) {
      const double W = kernel.value(std::sqrt(r2));
      weight += W;
      pressure += f.pressure[j] * W;
      density_moment += (f.density[j] * W) * r_wj;
      velocity += W * f.velocity[j];
    };
    grid.for_each_neighbour(w, f.position, gather, fluid_count);
    if (weight > 0.0) {
      // Adami et al. (2012), eq. 27, for a wall at rest in the frame of gravity.
      f.pressure[w] = std::max(0.0, (pressure + parameters.gravity.dot(density_moment)) / weight);
      f.density[w] = eos.density(f.pressure[w]);
      // Adami et al. (2012), eqs. 22-23.
      f.wall_velocity[w] = 2.0 * f.velocity[w] - velocity / weight;
    } else {
      f.pressure[w] = 0.0;
      f.density[w] = parameters.reference_density;
      f.wall_velocity[w] = f.velocity[w];
    }
  }
}

}  // namespace partimix::sph
