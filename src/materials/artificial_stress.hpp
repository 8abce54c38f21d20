#pragma once
// Monaghan's artificial stress against the tensile instability (Monaghan 2000, J. Comput. Phys.
// 159, 290; Gray, Monaghan & Swift 2001, section 4; docs/multi-material-sph.md, "Solid"): in the
// principal axes of a particle's stress sigma, each tensile principal stress sigma'_aa > 0 gives
// R'_aa = -epsilon sigma'_aa / rho^2 (0 where compressive), rotated back to the frame; the pair
// i, j then adds (R_i + R_j) f_ij^n to the momentum equation's stress term, f_ij = W(r_ij) /
// W(dp), which repels particles that clump under tension.
#include "core/vec.hpp"

namespace partimix::materials {

// R [m^5/(kg s^2), the units of sigma / rho^2] of a particle
// with stress sigma [Pa] and density rho, for the factor epsilon (0.3 in Gray et al.).
Mat3 artificial_stress(const Mat3& stress, double density, double epsilon);

}  // namespace partimix::materials
