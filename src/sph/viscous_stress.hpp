#pragma once
// The part of the viscous stress that the Morris term leaves out, for the stress-form viscous
// operator (docs/sph.md, "Viscous operators"; the seed's eqs. 14-15). With
// tau = eta_a (G + G^T), div tau = div(eta_a G) + div(eta_a G^T): the Morris pair term gives the
// first, and the second is the SPH divergence of T = eta_a G^T held per particle. G is the SPH
// velocity gradient (sph/velocity_gradient.hpp). Wall particles take the kernel-weighted mean of
// their fluid neighbours' T.
#include <cstddef>
#include <vector>

#include "materials/rheology.hpp"
#include "particles/cell_grid.hpp"
#include "sph/fields.hpp"
#include "sph/kernel_table.hpp"

namespace partimix::sph {

// Writes fields.shear_rate and fields.viscosity of the fluid particles [0, fluid_count) and
// fields.viscous_stress (T) of all particles. `gradient_kernel` gives G, `kernel` the wall
// means. Returns the largest apparent viscosity of the fluid.
double compute_viscous_stress(Fields& fields, std::size_t fluid_count, const CellGrid& grid,
                              const KernelTable& gradient_kernel, const KernelTable& kernel,
                              const materials::BoundedRheology& rheology, int dimensions,
                              bool corrected);

// The acceleration div(eta_a G^T) / rho of each fluid particle from the held stresses T,
// sum_j m_j (T_i / rho_i^2 + T_j / rho_j^2) grad_i W_ij over fluid and wall neighbours, as the
// stress form's pair term: the explicit part of the semi-implicit viscous step (docs/sph.md,
// "Implicit viscosity"). Writes `acceleration[0, fluid_count)`.
void compute_stress_divergence(const Fields& fields, std::size_t fluid_count, const CellGrid& grid,
                               const KernelTable& gradient_kernel, std::vector<Vec3>& acceleration);

}  // namespace partimix::sph
