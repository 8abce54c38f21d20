#pragma once
// The pair sums of the multi-material SPH scheme (docs/multi-material-sph.md, "The scheme"):
// momentum with each particle's full stress sigma = -p I + S, Monaghan's artificial viscosity
// and artificial stress, Morris's viscous term; the expansion rate that drives the density and
// the compression work; and the velocity gradient of the solids. Two pairings, chosen by the
// density treatment:
// - summation (grad-h; Price 2012, section 2.6; the seed's eq. 7 with f = 1 / Omega):
//     dv_i/dt = sum_j m_j [sigma_i / (Omega_i rho_i^2) grad W(h_i) + sigma_j / (Omega_j rho_j^2)
//               grad W(h_j)] + ...,   epsilon_i = sum_j m_j v_ij . grad W(h_i) / (Omega_i rho_i^2);
// - continuity (Colagrossi & Landrini 2003, for density ratios of 1,000):
//     dv_i/dt = sum_j m_j (sigma_i + sigma_j) / (rho_i rho_j) grad W-bar + ...,
//     epsilon_i = sum_j m_j v_ij . grad W-bar / (rho_i rho_j),   drho_i/dt = rho_i^2 epsilon_i,
// grad W-bar the mean of grad W(h_i) and grad W(h_j). Either way p_i epsilon_i is the compression
// work per unit mass, and the pair forces are antisymmetric, so energy and momentum are kept.
// The other terms (bars the pair means, v_ij = v_i - v_j, r_ij = x_i - x_j):
//   - Pi_ij grad W-bar, Pi_ij = (-alpha c mu_ij + beta mu_ij^2) / rho where v_ij . r_ij < 0;
//     mu_ij = h v_ij . r_ij / (r_ij^2 + 0.01 h^2) (Monaghan 1992), heating 1/2 Pi_ij v_ij . grad;
//   - (R_i + R_j) f_ij^4 grad W-bar, f_ij = W(r_ij, h) / W(dp_i, h), R the artificial stress;
//   - m_j (mu_i + mu_j) / (rho_i rho_j) r_ij . grad W-bar / (r_ij^2 + 0.01 h^2) v_ij (Morris et
//     al. 1997), heating -1/2 of it dotted with v_ij;
//   - L_i = [sum_j m_j / rho_j (v_j - v_i) (x) grad W-bar] B_i^-1, the velocity gradient with
//     the first-order correction B_i = sum_j m_j / rho_j (x_j - x_i) (x) grad W-bar (Randles &
//     Libersky 1996), uncorrected where det B_i < 0.1;
//   - g_i = sum_j m_j / rho_j grad W-bar, the gradient of unity: 0 inside, |g_i| the surface
//     per unit volume at a free surface (the ambient's heat flux).
// Pairs of bonded total Lagrangian solid particles skip the stress and artificial stress terms:
// their stress force is total_lagrangian.hpp's. A pair whose bond a crack has cut (bond_table.hpp)
// acts by contact alone: -(max(p_i, 0) + max(p_j, 0)) in place of sigma_i + sigma_j, no
// artificial stress, so that the faces of a crack push but do not pull.
#include <cstddef>
#include <span>

#include "core/vec.hpp"
#include "particles/cell_grid.hpp"
#include "sph/multi_material/bond_table.hpp"
#include "sph/scaled_kernel.hpp"

namespace partimix::sph {

enum class DensityPairing { summation, continuity };

struct MaterialParticles {
  std::span<const Vec3> position;
  std::span<const Vec3> velocity;
  std::span<const double> mass;
  std::span<const double> h;
  std::span<const double> density;
  std::span<const double> omega;            // 1 with the continuity pairing
  std::span<const double> pressure;         // gauge, p - p_ambient [Pa]
  std::span<const Mat3> deviatoric_stress;  // S [Pa], zero for fluids
  std::span<const Mat3> artificial_stress;  // R [m^5/(kg s^2)]
  std::span<const double> spacing;          // dp of f_ij, the particle's (m / rho)^(1/d)
  std::span<const double> sound_speed;      // [m/s]
  std::span<const double> viscosity;        // dynamic [Pa s]
  // The total Lagrangian solids' bonds: intact ones skip the stress and artificial stress terms
  // here, cut ones act by contact; null without such solids.
  const BondTable* bonds = nullptr;
};

struct ArtificialViscosity {
  double alpha = 1.0;
  double beta = 2.0;
};

struct MaterialRates {
  std::span<Vec3> acceleration;       // [m/s^2]
  std::span<double> expansion;        // epsilon [m^3/(kg s)]
  std::span<double> heating;          // viscous and artificial-viscous heating [W/kg]
  std::span<Mat3> velocity_gradient;  // L [1/s]
  std::span<Vec3> unity_gradient;     // g [1/m]
};

// Writes the rates of particles [0, count); `grid`'s radius covers support * h of every
// particle.
void material_rates(const MaterialParticles& particles, std::size_t count, const CellGrid& grid,
                    const ScaledKernel& kernel, DensityPairing pairing,
                    const ArtificialViscosity& viscosity, const MaterialRates& rates);

}  // namespace partimix::sph
