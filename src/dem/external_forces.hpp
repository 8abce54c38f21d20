#pragma once
// Forces on the grains from outside the DEM, held between the moments another method sets them
// (a coupled fluid; docs/cfd-dem.md, "One coupled step and the sub-cycles"): on grain i
//
//     f_i = F_i + K_i (Ω × (x_i - a) - v_i),
//
// F_i [N] held, K_i [kg/s] a linear drag coefficient on the grain's velocity, Ω × (x_i - a) a
// rigid rotation of the fluid about the axis through a, taken at the grain's present place (a
// fluid solved in a rotating frame: the drag then follows the grain round; Ω = 0 otherwise),
// applied at every half kick of the velocity Verlet step with the velocity at the kick's end:
// over a half kick h = Δt / 2,
//
//     v' = (v + h ((F_c + F_i + K_i w_i) / m_i + g)) / (1 + h K_i / m_i),    w_i = Ω × (x_i - a),
//
// backward Euler in the drag (docs/cfd-dem.md, "Stability of the sub-cycles"): stable whatever
// Δt K_i / m_i, so that a grain in a viscous paste may relax faster than the DEM's step, and then
// at its terminal velocity in one kick. The impulse h (F_i + K_i (w_i - v')) of each half kick is
// summed into J_i [N s], so that whoever set the forces knows exactly the momentum the grains
// received. Three fields of the store (not written to frames), so they follow the grains when the
// store is sorted and are part of checkpoints.
#include <vector>

#include "core/vec.hpp"

namespace partimix::dem {

struct ExternalForces {
  std::vector<Vec3>* force = nullptr;    // F_i
  std::vector<double>* drag = nullptr;   // K_i
  std::vector<Vec3>* impulse = nullptr;  // J_i, summed until reset by the setter
  Vec3 spin = Vec3::Zero();              // Ω [rad/s]
  Vec3 axis_point = Vec3::Zero();        // a [m]
};

}  // namespace partimix::dem
