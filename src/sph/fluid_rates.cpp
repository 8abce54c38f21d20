#include "sph/fluid_rates.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace partimix::sph {
namespace {

struct Rates {
  double density_rate = 0.0;
  Vec3 acceleration = Vec3::Zero();
};

// The sum over the neighbours of fluid particle i.
Rates rates_of(std::size_t i, const Fields& f, const CellGrid& grid, const KernelTable& kernel,
               const Parameters& p) {
  const double rho_i = f.density[i];
  const double p_over_rho2_i = f.pressure[i] / (rho_i * rho_i);
  const Vec3& v_i = f.velocity[i];
  const double eta_i = f.viscosity[i];
  const Mat3 tau_over_rho2_i = p.viscous_operator == ViscousOperator::stress
                                   ? Mat3(f.viscous_stress[i] / (rho_i * rho_i))
                                   : Mat3::Zero();
  const double diffusion_factor = 2.0 * p.delta * p.h * p.sound_speed;
  const double inverse_c2 = 1.0 / (p.sound_speed * p.sound_speed);
  Rates sum;
  grid.for_each_neighbour(i, f.position, [&](std::size_t j, const Vec3& r_ij, double r2) {
    if (j == i)
      return;
    const double r = std::sqrt(r2);
    const Vec3 grad = (kernel.derivative(r) / r) * r_ij;  // grad_i W_ij
    const double r_dot_grad = r_ij.dot(grad);
    const double rho_j = f.density[j];
    const double m_j = f.mass[j];
    const bool fluid_j = is_fluid(f.kind[j]);
    const Vec3 v_ij = v_i - f.velocity[j];
    sum.density_rate += m_j * v_ij.dot(grad);
    sum.acceleration -= (m_j * (p_over_rho2_i + f.pressure[j] / (rho_j * rho_j))) * grad;
    const Vec3 v_ij_viscous = fluid_j ? v_ij : Vec3(v_i - f.wall_velocity[j]);
    if (p.viscous_operator != ViscousOperator::none) {
      // Morris et al. (1997), eq. 8 with twice the pair's mean viscosity (arithmetic or
      // harmonic); a wall takes the viscosity of i.
      const double eta_j = fluid_j ? f.viscosity[j] : eta_i;
      const double eta_sum =
          p.harmonic_viscosity_mean ? 4.0 * eta_i * eta_j / (eta_i + eta_j) : eta_i + eta_j;
      sum.acceleration +=
          (m_j * eta_sum * r_dot_grad / (rho_i * rho_j * (r2 + p.eta2))) * v_ij_viscous;
    }
    if (p.viscous_operator == ViscousOperator::stress) {
      sum.acceleration += m_j * (tau_over_rho2_i + f.viscous_stress[j] / (rho_j * rho_j)) * grad;
    }
    const double approach = v_ij_viscous.dot(r_ij);
    if (p.artificial_viscosity > 0.0 && approach < 0.0) {
      const double mu_ij = p.h * approach / (r2 + p.eta2);
      const double pi_ij =
          -p.artificial_viscosity * p.sound_speed * mu_ij / (0.5 * (rho_i + rho_j));
      sum.acceleration -= (m_j * pi_ij) * grad;
    }
    if (p.diffusion != DensityDiffusion::none && fluid_j) {
      double difference = rho_j - rho_i;
      if (p.diffusion == DensityDiffusion::fourtakas) {
        difference += p.reference_density * p.hydrostatic_gravity.dot(r_ij) * inverse_c2;
      }
      sum.density_rate += diffusion_factor * difference * (-r_dot_grad / r2) * (m_j / rho_j);
    }
  });
  return sum;
}

}  // namespace

RateExtremes compute_fluid_rates(Fields& f, std::size_t fluid_count, const CellGrid& grid,
                                 const KernelTable& kernel, const Parameters& p) {
  const auto n = static_cast<std::ptrdiff_t>(fluid_count);
  double max_acceleration2 = 0.0;
  double max_speed2 = 0.0;
#pragma omp parallel for schedule(dynamic, 512) reduction(max : max_acceleration2, max_speed2)
  for (std::ptrdiff_t ii = 0; ii < n; ++ii) {
    const auto i = static_cast<std::size_t>(ii);
    const Rates rates = rates_of(i, f, grid, kernel, p);
    f.density_rate[i] = rates.density_rate;
    f.acceleration[i] = rates.acceleration + p.gravity;
    max_acceleration2 = std::max(max_acceleration2, f.acceleration[i].squaredNorm());
    max_speed2 = std::max(max_speed2, f.velocity[i].squaredNorm());
  }
  return {std::sqrt(max_acceleration2), std::sqrt(max_speed2)};
}

}  // namespace partimix::sph
