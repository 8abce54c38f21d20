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

// s_w = V_w sum_(w' of w's body) V_w' grad_w W_ww' (V = m / rho0): the part of the body's
// surface that wall particle w stands for, as an area vector pointing into the body, half the
// area in the continuum limit (docs/power.md, "Uniform parts of the load"). Over a body it sums
// to zero, and so do its moments about any point: each pair appears twice with opposite signs.
Vec3 body_area_vector(std::size_t w, const Fields& f, std::size_t fluid_count, const CellGrid& grid,
                      const KernelTable& kernel, const Parameters& p) {
  const std::int32_t own = (*f.body)[w];
  Vec3 sum = Vec3::Zero();
  grid.for_each_neighbour(
      w, f.position,
      [&](std::size_t j, const Vec3& r_wj, double r2) {
        if (j == w || (*f.body)[j] != own)
          return;
        const double r = std::sqrt(r2);
        sum += (f.mass[j] * kernel.derivative(r) / r) * r_wj;
      },
      f.position.size(), fluid_count);
  return (f.mass[w] / (p.reference_density * p.reference_density)) * sum;
}

}  // namespace

// docs/power.md, "Uniform parts of the load": on a solid body, the pair terms with the wall's
// own pressure taken off the fluid's, plus 2 p_w s_w; elsewhere the pair terms alone.
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
    const bool solid = f.solid != nullptr && f.body != nullptr && (*f.solid)[w] != 0;
    Vec3 force = Vec3::Zero();
    Vec3 couple = Vec3::Zero();
    bool wetted = false;
    const double inverse_density_w = 1.0 / f.density[w];
    const double p_w = f.pressure[w];
    const double reference = solid ? p_w : 0.0;  // the pressure taken off the pair terms
    const double wall_p_over_rho2 = reference * inverse_density_w * inverse_density_w;
    auto gather = [&](std::size_t i, const Vec3& r_wi, double r2) {
      PairCentre centre = pair_centre(i, f, p);
      centre.p_over_rho2 -= reference * centre.inverse_density * centre.inverse_density;
      const Vec3 grad = centre_gradient_factor(centre, std::sqrt(r2), kernel) * -r_wi;
      Vec3 acceleration =
          wall_pair_rates(centre, w, -r_wi, r2, inverse_density_w, f, kernel, p).acceleration +
          f.mass[w] * wall_p_over_rho2 * grad;
      if (rigid)
        acceleration += rigid_wall_traction(centre, w, grad, f);
      const Vec3 f_iw = -f.mass[i] * acceleration;
      force += f_iw;
      couple += (-0.5 * r_wi).cross(f_iw);
      wetted = true;
    };
    grid.for_each_neighbour(w, f.position, gather, fluid_count);
    if (solid && wetted)
      force += 2.0 * reference * body_area_vector(w, f, fluid_count, grid, kernel, p);
    loads.force[w] = force;
    loads.couple[w] = couple;
  }
}

}  // namespace partimix::sph
