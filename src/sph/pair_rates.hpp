#pragma once
// The pair terms of the density rate and acceleration of fluid particles (docs/sph.md,
// "Discrete equations"). A fluid pair's terms are computed once and given to both particles
// (fluid_pair_terms, used by the fluid rates over a half neighbour list); a fluid particle's
// wall neighbours act on it alone (wall_pair_rates, used by the fluid rates and by the wall
// loads, which sum -m_i times it over the fluid neighbours of a wall particle: docs/mixing-
// power.md, seed eq. 23). Both are written with F = (dW/dr) / r, grad_i W_ij = F r_ij, so that
// a pair costs one division for the kernel and one for each viscous term (docs/performance.md).
#include <algorithm>
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

// What the pair terms need of fluid particle i, computed once per i: with a variable smoothing
// length its h_i and the scales of its kernel to the reference h's table (docs/sph.md,
// "Variable smoothing length"), else h and 1.
struct PairCentre {
  std::size_t index = 0;
  double h = 0.0;
  double kernel_scale = 1.0;    // h / h_i
  double gradient_scale = 1.0;  // (h / h_i)^(d+1)
  double density = 0.0;
  double inverse_density = 0.0;
  double p_over_rho2 = 0.0;
  double viscosity = 0.0;
  Vec3 velocity = Vec3::Zero();
  Mat3 tau_over_rho2 = Mat3::Zero();
};

inline PairCentre pair_centre(std::size_t i, const Fields& f, const Parameters& p) {
  const double rho_i = f.density[i];
  PairCentre c;
  c.index = i;
  c.h = p.h;
  if (!f.kernel_scale.empty()) {
    c.kernel_scale = f.kernel_scale[i];
    c.gradient_scale = f.gradient_scale[i];
    c.h = p.h / c.kernel_scale;
  }
  c.density = rho_i;
  c.inverse_density = 1.0 / rho_i;
  c.p_over_rho2 = f.pressure[i] * c.inverse_density * c.inverse_density;
  c.viscosity = f.viscosity[i];
  c.velocity = f.velocity[i];
  if (p.viscous_operator == ViscousOperator::stress)
    c.tau_over_rho2 = f.viscous_stress[i] * (c.inverse_density * c.inverse_density);
  return c;
}

// Twice the pair's mean viscosity in the Morris term: eta_i + eta_j, or the harmonic
// 4 eta_i eta_j / (eta_i + eta_j) (sph.viscosity_mean).
inline double pair_viscosity(double eta_i, double eta_j, const Parameters& p) {
  return p.harmonic_viscosity_mean ? 4.0 * eta_i * eta_j / (eta_i + eta_j) : eta_i + eta_j;
}

// The Monaghan (1992) artificial viscosity Pi_ij = -alpha c0 mu_ij / rho_mean with
// mu_ij = h min(v_ij . r_ij, 0) / (r2 + eta2), h the pair's: zero for receding pairs, without a
// branch.
inline double artificial_viscosity(double approach, double r2, double rho_i, double rho_j, double h,
                                   const Parameters& p) {
  return -p.artificial_viscosity * p.sound_speed * h * std::min(approach, 0.0) /
         ((r2 + p.eta2) * 0.5 * (rho_i + rho_j));
}

// The stress form's pair term per unit mass of neighbour j, (T_i / rho_i^2 + T_j / rho_j^2)
// grad_i W_ij with T = eta_a G^T (docs/sph.md, "Viscous operators").
[[gnu::always_inline]] inline Vec3 stress_pair_term(const Mat3& tau_over_rho2_i, std::size_t j,
                                                    double inverse_density_j, const Vec3& grad,
                                                    const Fields& f) {
  return (tau_over_rho2_i + f.viscous_stress[j] * (inverse_density_j * inverse_density_j)) * grad;
}

// The acceleration of fluid particle i per unit mass of neighbour j (docs/sph.md): pressure,
// Morris viscosity with the pair viscosity eta_sum and the velocity difference v_viscous (a
// wall's ghost velocity for a wall), stress form, artificial viscosity with the pair's h.
// grad = F r_ij.
[[gnu::always_inline]] inline Vec3 momentum_per_mass(const PairCentre& i, std::size_t j,
                                                     const Vec3& r_ij, double r2,
                                                     double gradient_factor,
                                                     double inverse_density_j, double eta_sum,
                                                     double h, const Vec3& v_viscous,
                                                     const Fields& f, const Parameters& p) {
  const Vec3 grad = gradient_factor * r_ij;
  const double p_over_rho2_j = f.pressure[j] * inverse_density_j * inverse_density_j;
  Vec3 acceleration = -(i.p_over_rho2 + p_over_rho2_j) * grad;
  if (p.viscous_operator != ViscousOperator::none) {
    // Morris et al. (1997), eq. 8 with twice the pair's mean viscosity, r_ij . grad = F r2.
    acceleration +=
        (i.inverse_density * inverse_density_j * eta_sum * gradient_factor * r2 / (r2 + p.eta2)) *
        v_viscous;
  }
  if (p.viscous_operator == ViscousOperator::stress)
    acceleration += stress_pair_term(i.tau_over_rho2, j, inverse_density_j, grad, f);
  if (p.artificial_viscosity > 0.0)
    acceleration -=
        artificial_viscosity(v_viscous.dot(r_ij), r2, i.density, f.density[j], h, p) * grad;
  return acceleration;
}

// What fluid particles i and j share: with it, a_i += m_j A, a_j -= m_i A,
// drho_i += m_j s + V_j d and drho_j += m_i s - V_i d (V = m / rho).
struct SharedPairTerms {
  Vec3 acceleration = Vec3::Zero();  // A
  double density_rate = 0.0;         // s = v_ij . grad_i W_ij
  double diffusion = 0.0;            // d, the delta-SPH term per neighbour volume
};

// F = (dW/dr) / r of fluid particle i's kernel at distance r, read from the reference h's table.
[[gnu::always_inline]] inline double centre_gradient_factor(const PairCentre& i, double r,
                                                            const KernelTable& kernel) {
  return i.gradient_scale * kernel.derivative(r * i.kernel_scale) / r;
}

// What fluid particles i and j share of the kernel: F of grad_i W_ij = F r_ij and the pair's h;
// with a variable smoothing length the mean of their kernels' F and of their h (docs/sph.md,
// "Variable smoothing length").
struct PairKernel {
  double gradient_factor = 0.0;
  double h = 0.0;
};

[[gnu::always_inline]] inline PairKernel pair_kernel(const PairCentre& i, std::size_t j, double r,
                                                     const Fields& f, const KernelTable& kernel,
                                                     const Parameters& p) {
  if (f.kernel_scale.empty())
    return {kernel.derivative(r) / r, p.h};
  const double scale_j = f.kernel_scale[j];
  return {0.5 * (centre_gradient_factor(i, r, kernel) +
                 f.gradient_scale[j] * kernel.derivative(r * scale_j) / r),
          0.5 * (i.h + p.h / scale_j)};
}

// Fluid particles i (its centre) and j: r_ij = x_i - x_j, 0 < r2 = |r_ij|^2,
// inverse_density_j = 1 / rho_j.
[[gnu::always_inline]] inline SharedPairTerms fluid_pair_terms(
    const PairCentre& i, std::size_t j, const Vec3& r_ij, double r2, double inverse_density_j,
    const Fields& f, const KernelTable& kernel, const Parameters& p) {
  const PairKernel pair = pair_kernel(i, j, std::sqrt(r2), f, kernel, p);
  const double gradient_factor = pair.gradient_factor;
  const Vec3 v_ij = i.velocity - f.velocity[j];
  SharedPairTerms terms;
  terms.density_rate = gradient_factor * v_ij.dot(r_ij);
  terms.acceleration =
      momentum_per_mass(i, j, r_ij, r2, gradient_factor, inverse_density_j,
                        pair_viscosity(i.viscosity, f.viscosity[j], p), pair.h, v_ij, f, p);
  if (p.diffusion != DensityDiffusion::none) {
    double difference = f.density[j] - i.density;
    if (p.diffusion == DensityDiffusion::fourtakas) {
      difference +=
          p.reference_density * p.hydrostatic_gravity.dot(r_ij) / (p.sound_speed * p.sound_speed);
    }
    // docs/sph.md, "Density diffusion", with r_ij . grad_i W_ij / r2 = F.
    terms.diffusion = 2.0 * p.delta * pair.h * p.sound_speed * difference * (-gradient_factor);
  }
  return terms;
}

// Fluid particle i (its centre) and wall particle w: the wall's velocity in the continuity
// term, its no-slip ghost velocity in the viscous terms, the viscosity and kernel of i, no
// diffusion.
[[gnu::always_inline]] inline PairRates wall_pair_rates(const PairCentre& i, std::size_t w,
                                                        const Vec3& r_iw, double r2,
                                                        double inverse_density_w, const Fields& f,
                                                        const KernelTable& kernel,
                                                        const Parameters& p) {
  const double gradient_factor = centre_gradient_factor(i, std::sqrt(r2), kernel);
  const double m_w = f.mass[w];
  PairRates rates;
  rates.density_rate = m_w * gradient_factor * (i.velocity - f.velocity[w]).dot(r_iw);
  rates.acceleration = m_w * momentum_per_mass(i, w, r_iw, r2, gradient_factor, inverse_density_w,
                                               pair_viscosity(i.viscosity, i.viscosity, p), i.h,
                                               i.velocity - f.wall_velocity[w], f, p);
  return rates;
}

}  // namespace partimix::sph
