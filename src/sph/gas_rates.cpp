#include "sph/gas_rates.hpp"

#include <algorithm>
#include <cmath>

namespace partimix::sph {

namespace {

// Monaghan's Pi_ij (1992), 0 for receding pairs.
double artificial_viscosity(const GasParticles& p, std::size_t i, std::size_t j, const Vec3& rij,
                            double r2, const ArtificialViscosity& av) {
  const double approach = (p.velocity[i] - p.velocity[j]).dot(rij);
  if (approach >= 0.0)
    return 0.0;
  const double h = 0.5 * (p.h[i] + p.h[j]);
  const double mu = h * approach / (r2 + 0.01 * h * h);
  const double c = 0.5 * (p.sound_speed[i] + p.sound_speed[j]);
  const double rho = 0.5 * (p.density[i] + p.density[j]);
  return (-av.alpha * c * mu + av.beta * mu * mu) / rho;
}

}  // namespace

void gas_rates(const GasParticles& p, std::size_t count, const CellGrid& grid,
               const ScaledKernel& kernel, const ArtificialViscosity& av,
               std::span<Vec3> acceleration, std::span<double> energy_rate) {
  const double support = kernel.support();
  const auto n = static_cast<std::ptrdiff_t>(count);
#pragma omp parallel for schedule(dynamic, 256)
  for (std::ptrdiff_t ii = 0; ii < n; ++ii) {
    const auto i = static_cast<std::size_t>(ii);
    const double pi_term = p.pressure[i] / (p.omega[i] * p.density[i] * p.density[i]);
    Vec3 a = Vec3::Zero();
    double work = 0.0;
    double heating = 0.0;
    grid.for_each_neighbour(
        i, p.position,
        [&](std::size_t j, const Vec3& rij, double r2) {
          const double reach = support * std::max(p.h[i], p.h[j]);
          if (j == i || r2 >= reach * reach)
            return;
          const double r = std::sqrt(r2);
          const Vec3 unit = rij / r;
          const Vec3 grad_i = kernel.derivative(r, p.h[i]) * unit;
          const Vec3 grad_j = kernel.derivative(r, p.h[j]) * unit;
          const double pj_term = p.pressure[j] / (p.omega[j] * p.density[j] * p.density[j]);
          const double viscous = artificial_viscosity(p, i, j, rij, r2, av);
          const Vec3 grad_mean = 0.5 * (grad_i + grad_j);
          const Vec3 vij = p.velocity[i] - p.velocity[j];
          a -= p.mass[j] * (pi_term * grad_i + pj_term * grad_j + viscous * grad_mean);
          work += p.mass[j] * vij.dot(grad_i);
          heating += 0.5 * p.mass[j] * viscous * vij.dot(grad_mean);
        },
        count);
    acceleration[i] = a;
    energy_rate[i] = pi_term * work + heating;
  }
}

}  // namespace partimix::sph
