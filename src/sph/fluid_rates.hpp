#pragma once
// Density rate and acceleration of every fluid particle (docs/sph.md, "Discrete equations"):
// continuity in the seed's form (eq. 13) plus delta-SPH diffusion (Molteni and Colagrossi 2009;
// Fourtakas et al. 2019), pressure gradient (seed eq. 14 with sigma = -p I), laminar viscosity
// as the Morris term (seed eq. 17) or the divergence of the viscous stress (seed eqs. 14-15),
// and Monaghan artificial viscosity (seed eqs. 18-19).
#include "particles/cell_grid.hpp"
#include "sph/fields.hpp"
#include "sph/kernel_table.hpp"
#include "sph/parameters.hpp"

namespace partimix::sph {

struct RateExtremes {
  double max_acceleration = 0.0;  // over fluid particles [m/s^2]
  double max_speed = 0.0;         // over fluid particles [m/s]
};

// Needs pressures of all particles, the wall state and (stress form) the viscous stresses of
// this instant. Fluid particles are
// [0, fluid_count) of the fields.
RateExtremes compute_fluid_rates(Fields& fields, std::size_t fluid_count, const CellGrid& grid,
                                 const KernelTable& gradient_kernel, const Parameters& parameters);

}  // namespace partimix::sph
