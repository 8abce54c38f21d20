#include "sph/wall_state.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include <Eigen/Geometry>

namespace partimix::sph {
namespace {

// The largest ratio beta of the extrapolated ghost velocity. The ghost velocity lags a step
// behind the fluid's, and a larger ratio feeds more of the fluid's noise back at large viscous
// Courant numbers: on the 2D rotating plate (dp = 5 mm, Re = 0.5, flow_cfl 0.2) the torque's
// standard deviation is 0.62 with 2, 1.14 with 4 and 2.12 uncapped (docs/sph.md, "Walls").
constexpr double kLargestGhostRatio = 2.0;

// beta = d_w / d_f of wall particle w, its depth below the surface over the mean distance from
// the surface of the fluid it sees (mean_offset = x~_w - x_w), for a profile linear in the
// distance from the wall (docs/sph.md, "Walls"); 1 (Adami's mirror) without a surface normal.
double ghost_ratio(const Fields& f, std::size_t w, const Vec3& mean_offset,
                   const Parameters& parameters) {
  if (!parameters.extrapolated_wall_velocity || f.surface_normal == nullptr ||
      f.surface_depth == nullptr || (*f.surface_normal)[w].isZero())
    return 1.0;
  const double depth = (*f.surface_depth)[w];
  const double fluid_distance = mean_offset.dot((*f.surface_normal)[w]) - depth;
  if (fluid_distance * kLargestGhostRatio <= depth)
    return kLargestGhostRatio;
  return depth / fluid_distance;
}

}  // namespace

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
    Vec3 offset = Vec3::Zero();
    auto gather = [&](std::size_t j, const Vec3& r_wj, double r2) {
      const double W = kernel.value(std::sqrt(r2));
      weight += W;
      pressure += f.pressure[j] * W;
      density_moment += (f.density[j] * W) * r_wj;
      velocity += W * f.velocity[j];
      offset -= W * r_wj;
    };
    grid.for_each_neighbour(w, f.position, gather, fluid_count);
    if (weight > 0.0) {
      // Adami et al. (2012), eq. 27, with the wall's own acceleration a_w; kept >= 0 unless the
      // case allows tension at walls (docs/sph.md, "Walls").
      Vec3 relative_gravity = parameters.gravity;
      if (f.body_acceleration != nullptr)
        relative_gravity -= (*f.body_acceleration)[w];
      const double extrapolated = (pressure + relative_gravity.dot(density_moment)) / weight;
      f.pressure[w] =
          parameters.negative_wall_pressure ? extrapolated : std::max(0.0, extrapolated);
      f.density[w] = eos.density(f.pressure[w]);
      // Adami et al. (2012), eqs. 22-23, for the velocity relative to the body's rigid motion
      // (docs/sph.md, "Walls"): the rigid velocity at the fluid's mean position adds
      // omega x (x_mean - x_w); extrapolated with the ratio beta of depths.
      Vec3 relative = velocity / weight - f.velocity[w];
      if (f.angular_velocity != nullptr)
        relative -= (*f.angular_velocity)[w].cross(offset / weight);
      const double ratio = ghost_ratio(f, w, offset / weight, parameters);
      f.wall_velocity[w] = f.velocity[w] - ratio * relative;
      f.ghost_weight[w] = ratio / weight;
    } else {
      f.pressure[w] = 0.0;
      f.density[w] = parameters.reference_density;
      f.wall_velocity[w] = f.velocity[w];
      f.ghost_weight[w] = 0.0;
    }
  }
}

}  // namespace partimix::sph
