#pragma once
// The rotating frame's fictitious forces in the grid fluid's momentum predictor (docs/cfd.md,
// "Moving walls and the rotating frame"): on each open face of component a,
//
//     r_f += ε_f ρ_f [-2 Ω × ũ - Ω × (Ω × (x_f - a)) - (dΩ/dt) × (x_f - a)]_a
//
// with ũ = (3 u^n - u^{n-1}) / 2, the velocity extrapolated to the middle of the step (the
// Coriolis term's Adams-Bashforth estimate: forward Euler would make a free inertial oscillation
// grow by (2 Ω Δt)² / 2 each step), its components across a averaged from the four faces around
// f. The centrifugal and Euler terms are body forces at the face centre x_f.
#include "cfd/flow_mask.hpp"
#include "cfd/fluid_frame.hpp"
#include "grid/staggered_grid.hpp"

namespace partimix::cfd {

void add_frame_forces(const grid::StaggeredGrid& grid, const FlowMask& mask,
                      const FrameForces& forces, const FaceArrays& density,
                      const FaceArrays& void_fraction, const FaceArrays& velocity, FaceArrays& rhs);

}  // namespace partimix::cfd
