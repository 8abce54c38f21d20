#pragma once
// The numbers the SPH interaction loops need, resolved once at set-up from the case
// (docs/sph.md gives each term and its source).
#include "core/vec.hpp"

namespace partimix::sph {

enum class DensityDiffusion { none, molteni, fourtakas };

// Laminar viscous term of the momentum equation (docs/sph.md, "Viscous operators").
enum class ViscousOperator { none, morris, stress };

struct Parameters {
  int dimensions = 3;
  double spacing = 0.0;                     // dp [m]
  double h = 0.0;                           // smoothing length [m]
  double eta2 = 0.0;                        // 0.01 h^2, keeps 1 / r^2 terms finite (seed, eq. 17)
  double reference_density = 0.0;           // rho0 [kg/m^3]
  double sound_speed = 0.0;                 // c0 [m/s]
  Vec3 gravity = Vec3::Zero();              // body acceleration [m/s^2]
  Vec3 hydrostatic_gravity = Vec3::Zero();  // gravity without its periodic-axis components
  ViscousOperator viscous_operator = ViscousOperator::morris;
  bool harmonic_viscosity_mean = false;  // pair viscosity of the Morris term
  double artificial_viscosity = 0.0;     // Monaghan alpha
  DensityDiffusion diffusion = DensityDiffusion::fourtakas;
  double delta = 0.1;
  bool negative_wall_pressure = false;  // false: the wall pressure is kept >= 0
  // Ghost velocity by linear extrapolation with the wall particle's depth (docs/sph.md, "Walls");
  // false: Adami et al.'s mirror of the fluid's mean.
  bool extrapolated_wall_velocity = false;
};

}  // namespace partimix::sph
