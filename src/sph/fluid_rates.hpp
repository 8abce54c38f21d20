#pragma once
// Density rate and acceleration of every fluid particle (docs/sph.md, "Discrete equations"):
// continuity in the seed's form (eq. 13) plus delta-SPH diffusion (Molteni and Colagrossi 2009;
// Fourtakas et al. 2019), pressure gradient (seed eq. 14 with sigma = -p I), laminar viscosity
// as the Morris term (seed eq. 17) or the divergence of the viscous stress (seed eqs. 14-15),
// and Monaghan artificial viscosity (seed eqs. 18-19).
#include <vector>

#include "particles/neighbour_list.hpp"
#include "sph/fields.hpp"
#include "sph/kernel_table.hpp"
#include "sph/parameters.hpp"

namespace partimix::sph {

struct RateExtremes {
  double max_acceleration = 0.0;  // over fluid particles [m/s^2]
  double max_speed = 0.0;         // over fluid particles [m/s]
};

// Scratch of the fluid rates, kept between calls so that they do not allocate: 1 / rho of
// every particle, so that the pair terms multiply instead of divide, and each thread's share of
// the rates of the fluid particles it was given as partners, reduced in thread order
// (DESIGN.md, "Data and speed": results depend on the thread count by round-off only).
struct RateBuffers {
  std::vector<double> inverse_density;
  std::vector<std::vector<Vec3>> acceleration;
  std::vector<std::vector<double>> density_rate;
};

// Needs pressures of all particles, the wall state and (stress form) the viscous stresses of
// this instant, and `list` up to date for the current positions with count = split =
// fluid_count: fluid particles are [0, fluid_count) of the fields. Each fluid pair is computed
// once and given to both.
RateExtremes compute_fluid_rates(Fields& fields, std::size_t fluid_count, const NeighbourList& list,
                                 const KernelTable& gradient_kernel, const Parameters& parameters,
                                 RateBuffers& buffers);

}  // namespace partimix::sph
