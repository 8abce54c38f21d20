#pragma once
// Hooke's law for the deviatoric stress in the Jaumann (co-rotational) rate (Gray, Monaghan &
// Swift 2001, Comput. Methods Appl. Mech. Eng. 190, 6641; docs/multi-material-sph.md,
// "Solid"):
//   dS/dt = 2 G (D - tr(D) / 3 I) + S Omega^T + Omega S,
// with D = (L + L^T) / 2 the strain rate and Omega = (L - L^T) / 2 the spin of the velocity
// gradient L_ab = dv_a / dx_b. In a rigid rotation (D = 0) the stress turns with the body.
#include "core/vec.hpp"

namespace partimix::materials {

// dS/dt [Pa/s] for deviatoric stress S [Pa], velocity gradient L [1/s], shear modulus G [Pa].
Mat3 jaumann_stress_rate(const Mat3& deviatoric_stress, const Mat3& velocity_gradient,
                         double shear_modulus);

}  // namespace partimix::materials
