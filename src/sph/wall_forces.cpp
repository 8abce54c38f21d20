#include "sph/wall_forces.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include <Eigen/Geometry>

#include "sph/pair_rates.hpp"

namespace partimix::sph {

namespace {

// The pair term m_w (T_i / rho_i^2 + T_w / rho_w^2) grad_i W_iw with T_i = T_w = eta_i [omega x]^T,
// [omega x]^T g = -omega x g: the acceleration of fluid particle i.
Vec3 rigid_wall_traction(const PairCentre& i, std::size_t w, const Vec3& grad, const Fields& f) {
  const double rho_w = f.density[w];
  const double factor =
      f.mass[w] * i.viscosity * (1.0 / (i.density * i.density) + 1.0 / (rho_w * rho_w));
  return -factor * (*f.angular_velocity)[w].cross(grad);
}

}  // namespace

void compute_wall_forces(const Fields& f, std::size_t fluid_count, const CellGrid& grid,
                         const KernelTable& kernel, const Parameters& p, WallTraction traction,
                         WallLoads loads) {
  const bool rigid = traction == WallTraction::rigid_wall && f.angular_velocity != nullptr;
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
    const double inverse_density_w = 1.0 / f.density[w];
    auto gather = [&](std::size_t i, const Vec3& r_wi, double r2) {
      const PairCentre centre = pair_centre(i, f, p);
      Vec3 acceleration =
          wall_pair_rates(centre, w, -r_wi, r2, inverse_density_w, f, kernel, p).acceleration;
      if (rigid) {
        const double r = std::sqrt(r2);
        acceleration += rigid_wall_traction(centre, w, (kernel.derivative(r) / r) * -r_wi, f);
      }
      const Vec3 f_iw = -f.mass[i] * acceleration;
      force += f_iw;
      couple += (-0.5 * r_wi).cross(f_iw);
    };
    grid.for_each_neighbour(w, f.position, gather, fluid_count);
    loads.force[w] = force;
    loads.couple[w] = couple;
  }
}

}  // namespace partimix::sph
