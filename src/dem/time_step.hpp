#pragma once
// The time-step scales of DEM (docs/dem.md, "Motion and time step").
#include "dem/pair_properties.hpp"

namespace partimix::dem {

// Rayleigh time t_R = pi R sqrt(rho / G) / (0.1631 nu + 0.8766), G = E / (2 (1 + nu)) (Li, Xu
// and Thornton 2005).
double rayleigh_time(double radius, double density, const Material& material);

// Contact time of the undamped linear spring between two equal spheres of mass m:
// pi sqrt(m* / k_n), m* = m / 2.
double linear_contact_time(double mass, double stiffness);

}  // namespace partimix::dem
