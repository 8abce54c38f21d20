#pragma once
// Heat conduction between SPH particles of any materials (docs/multi-material-sph.md, "Heat
// conduction"; Cleary & Monaghan 1999, J. Comput. Phys. 148, 227; the seed's eq. 10):
//   de_i/dt = sum_j 4 m_j / (rho_i rho_j) k_i k_j / (k_i + k_j) (T_i - T_j)
//             r_ij . grad_i W_ij / (r_ij^2 + 0.01 h^2),
// with each particle's own smoothing length: grad W_ij the mean of grad W(h_i) and grad W(h_j),
// h the pair's mean.
// The harmonic mean of the conductivities keeps the heat flux continuous across a material
// interface, and each pair's exchange is antisymmetric, so that sum_i m_i de_i/dt = 0.
#include <cstddef>
#include <span>

#include "core/vec.hpp"
#include "particles/cell_grid.hpp"
#include "sph/scaled_kernel.hpp"

namespace partimix::sph {

// The particles' state that conduction reads, indexed alike.
struct ThermalParticles {
  std::span<const Vec3> position;
  std::span<const double> h;             // smoothing length [m]
  std::span<const double> mass;          // [kg]
  std::span<const double> density;       // [kg/m^3]
  std::span<const double> temperature;   // [K]
  std::span<const double> conductivity;  // k [W/(m K)]
};

// Adds conduction's de/dt [W/kg] of particles [0, count) to energy_rate; neighbours are those of
// `grid` in [0, count), whose radius covers support * h of every particle.
void add_conduction_rates(const ThermalParticles& particles, std::size_t count,
                          const CellGrid& grid, const ScaledKernel& kernel,
                          std::span<double> energy_rate);

}  // namespace partimix::sph
