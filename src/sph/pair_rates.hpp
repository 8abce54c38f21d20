#pragma once
// The contribution of one neighbour j to the density rate and acceleration of fluid particle i
// (docs/sph.md, "Discrete equations"). Shared by the fluid rates, which sum it over all
// neighbours of i, and the wall loads, which sum -m_i times its acceleration over the fluid
// neighbours of a wall particle j (docs/mixing-power.md, seed eq. 23).
#include <cmath>
#include <cstddef>

#include "sph/fields.hpp"
#include "sph/kernel_table.hpp"
#include "sph/parameters.hpp"

namespace partimix::sph {

struct PairRates {
  double density_rate = 0.0;
  Vec3 acceleration = Vec3::Zero();
};

// What the pair terms need of fluid particle i, computed once per i.
struct PairCentre {
  std::size_t index = 0;
  double density = 0.0;
  double p_over_rho2 = 0.0;
  double viscosity = 0.0;
  Vec3 velocity = Vec3::Zero();
  Mat3 tau_over_rho2 = Mat3::Zero();
};

inline PairCentre pair_centre(std::size_t i, const Fields& f, const Parameters& p) {
  const double rho_i = f.density[i];
  PairCentre c;
  c.index = i;
  c.density = rho_i;
  c.p_over_rho2 = f.pressure[i] / (rho_i * rho_i);
  c.viscosity = f.viscosity[i];
  c.velocity = f.velocity[i];
  if (p.viscous_operator == ViscousOperator::stress)
    c.tau_over_rho2 = f.viscous_stress[i] / (rho_i * rho_i);
  return c;
}

// Twice the pair's mean viscosity in the Morris term: eta_i + eta_j, or the harmonic
// 4 eta_i eta_j / (eta_i + eta_j) (sph.viscosity_mean).
inline double pair_viscosity(double eta_i, double eta_j, const Parameters& p) {
  return p.harmonic_viscosity_mean ? 4.0 * eta_i * eta_j / (eta_i + eta_j) : eta_i + eta_j;
}

// r_ij = x_i - x_j, r2 = |r_ij|^2 > 0.
inline PairRates pair_rates(const PairCentre& i, std::size_t j, const Vec3& r_ij, double r2,
                            const Fields& f, const KernelTable& kernel, const Parameters& p) {
  const double r = std::sqrt(r2);
  const Vec3 grad = (kernel.derivative(r) / r) * r_ij;  // grad_i W_ij
  const double r_dot_grad = r_ij.dot(grad);
  const double rho_i = i.density;
  const double rho_j = f.density[j];
  const double m_j = f.mass[j];
  const bool fluid_j = is_fluid(f.kind[j]);
  const Vec3 v_ij = i.velocity - f.velocity[j];
  PairRates rates;
  rates.density_rate = m_j * v_ij.dot(grad);
  rates.acceleration = -(m_j * (i.p_over_rho2 + f.pressure[j] / (rho_j * rho_j))) * grad;
  const Vec3 v_ij_viscous = fluid_j ? v_ij : Vec3(i.velocity - f.wall_velocity[j]);
  if (p.viscous_operator != ViscousOperator::none) {
    // Morris et al. (1997), eq. 8 with twice the pair's mean viscosity (arithmetic or
    // harmonic); a wall takes the viscosity of i.
    const double eta_i = i.viscosity;
    const double eta_j = fluid_j ? f.viscosity[j] : eta_i;
    const double eta_sum = pair_viscosity(eta_i, eta_j, p);
    rates.acceleration +=
        (m_j * eta_sum * r_dot_grad / (rho_i * rho_j * (r2 + p.eta2))) * v_ij_viscous;
  }
  if (p.viscous_operator == ViscousOperator::stress) {
    rates.acceleration += m_j * (i.tau_over_rho2 + f.viscous_stress[j] / (rho_j * rho_j)) * grad;
  }
  const double approach = v_ij_viscous.dot(r_ij);
  if (p.artificial_viscosity > 0.0 && approach < 0.0) {
    const double mu_ij = p.h * approach / (r2 + p.eta2);
    const double pi_ij = -p.artificial_viscosity * p.sound_speed * mu_ij / (0.5 * (rho_i + rho_j));
    rates.acceleration -= (m_j * pi_ij) * grad;
  }
  if (p.diffusion != DensityDiffusion::none && fluid_j) {
    double difference = rho_j - rho_i;
    if (p.diffusion == DensityDiffusion::fourtakas) {
      difference +=
          p.reference_density * p.hydrostatic_gravity.dot(r_ij) / (p.sound_speed * p.sound_speed);
    }
    const double diffusion_factor = 2.0 * p.delta * p.h * p.sound_speed;
    rates.density_rate += diffusion_factor * difference * (-r_dot_grad / r2) * (m_j / rho_j);
  }
  return rates;
}

}  // namespace partimix::sph
