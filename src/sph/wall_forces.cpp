#include "sph/wall_forces.hpp"

#include <algorithm>
#include <cstddef>

#include <Eigen/Geometry>

#include "sph/pair_rates.hpp"

namespace partimix::sph {

void compute_wall_forces(const Fields& f, std::size_t fluid_count, const CellGrid& grid,
                         const KernelTable& kernel, const Parameters& p, WallLoads loads) {
  const auto fluid_end = static_cast<std::ptrdiff_t>(fluid_count);
  std::fill(loads.force.begin(), loads.force.begin() + fluid_end, Vec3::Zero());
  std::fill(loads.couple.begin(), loads.couple.begin() + fluid_end, Vec3::Zero());
  const auto first = static_cast<std::ptrdiff_t>(fluid_count);
  const auto n = static_cast<std::ptrdiff_t>(f.position.size());
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t ww = first; ww < n; ++ww) {
    const auto w = static_cast<std::size_t>(ww);
    Vec3 force = Vec3::Zero();
    Vec3 couple = Vec3::Zero();
    auto gather = [&](std::size_t i, const Vec3& r_wi, double r2) {
      const PairRates pair = pair_rates(pair_centre(i, f, p), w, -r_wi, r2, f, kernel, p);
      const Vec3 f_iw = -f.mass[i] * pair.acceleration;
      force += f_iw;
      couple += (-0.5 * r_wi).cross(f_iw);
    };
    grid.for_each_neighbour(w, f.position, gather, fluid_count);
    loads.force[w] = force;
    loads.couple[w] = couple;
  }
}

}  // namespace partimix::sph
