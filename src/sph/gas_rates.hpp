#pragma once
// The momentum and energy equations of compressible SPH with a variable smoothing length
// (docs/multi-material-sph.md, "The scheme"; Price 2012, J. Comput. Phys. 231, 759, section 2.6;
// the seed's eq. 7 with f = 1 / Omega), with Monaghan's artificial viscosity (1992):
//   dv_i/dt = -sum_j m_j [P_i / (Omega_i rho_i^2) grad_i W_ij(h_i)
//                         + P_j / (Omega_j rho_j^2) grad_i W_ij(h_j) + Pi_ij grad_i W_ij(h_bar)],
//   de_i/dt = P_i / (Omega_i rho_i^2) sum_j m_j v_ij . grad_i W_ij(h_i)
//             + 1/2 sum_j m_j Pi_ij v_ij . grad_i W_ij(h_bar),
//   Pi_ij = (-alpha c_bar mu_ij + beta mu_ij^2) / rho_bar where v_ij . r_ij < 0 (else 0),
//   mu_ij = h_bar v_ij . r_ij / (r_ij^2 + 0.01 h_bar^2),
// bars the pair's means; grad_i W_ij(h_bar) is taken as the mean of the two particles' gradients.
#include <cstddef>
#include <span>

#include "core/vec.hpp"
#include "particles/cell_grid.hpp"
#include "sph/scaled_kernel.hpp"

namespace partimix::sph {

struct GasParticles {
  std::span<const Vec3> position;
  std::span<const Vec3> velocity;
  std::span<const double> mass;
  std::span<const double> h;
  std::span<const double> density;
  std::span<const double> omega;
  std::span<const double> pressure;
  std::span<const double> sound_speed;
};

struct ArtificialViscosity {
  double alpha = 1.0;
  double beta = 2.0;
};

// Writes dv/dt and de/dt of particles [0, count), neighbours from `grid` (whose radius covers
// support * h of every particle) in [0, count).
void gas_rates(const GasParticles& particles, std::size_t count, const CellGrid& grid,
               const ScaledKernel& kernel, const ArtificialViscosity& viscosity,
               std::span<Vec3> acceleration, std::span<double> energy_rate);

}  // namespace partimix::sph
