#pragma once
// The temperatures that conduction reads at a temperature (Dirichlet) boundary
// (docs/multi-material-sph.md, "Heat conduction"): a particle held at T_b (its material's
// `fixed_temperature`) that has free neighbours f conducts at the ghost temperature
//   T_g = 2 T_b - T~,   T~ = sum_f W(r_gf, h_g) T_f / sum_f W(r_gf, h_g),
// the wall extrapolation of Adami, Hu & Adams (2012, J. Comput. Phys. 231, 7057, eqs. 22-23, there
// of the no-slip velocity) applied to T, so that the free particles' profile continues through the
// boundary as if T_b held at its surface, rather than stopping flat at T_b (which leaves the
// boundary's heat flux short by O(h) of the heated depth). Free particles read their own T.
#include <cstddef>
#include <cstdint>
#include <span>

#include "core/vec.hpp"
#include "particles/cell_grid.hpp"
#include "sph/scaled_kernel.hpp"

namespace partimix::sph {

struct DirichletParticles {
  std::span<const Vec3> position;
  std::span<const double> h;            // smoothing length [m]
  std::span<const double> temperature;  // [K]; T_b for the held particles
  std::span<const std::uint8_t> held;   // 1: the particle's temperature is held
};

// The temperatures conduction reads, of particles [0, count), into `conducted`; neighbours are
// those of `grid` in [0, count), whose radius covers support * h of every particle.
void dirichlet_temperatures(const DirichletParticles& particles, std::size_t count,
                            const CellGrid& grid, const ScaledKernel& kernel,
                            std::span<double> conducted);

}  // namespace partimix::sph
