#pragma once
// Settings of the weakly-compressible SPH solver, as read from the `sph:` section of a case
// file (docs/case-reference.md lists each key with unit and default; docs/sph.md the equations).
#include <optional>
#include <string>

#include "core/vec.hpp"
#include "sph/multi_material/material_spec.hpp"

namespace partimix::sph {

struct TimeStepFactors {
  double cfl = 0.2;         // dt <= cfl * h / (c0 + |u|max)
  double flow_cfl = 0.1;    // incompressible: dt <= flow_cfl * h / U
  double viscous = 0.125;   // dt <= viscous * h^2 / nu
  double force = 0.25;      // dt <= force * sqrt(h / |a|max)
  double conductive = 0.1;  // multi_material: dt <= conductive * rho c_v h^2 / k
  double capillary = 0.25;  // multi_material: dt <= capillary * sqrt(rho h^3 / (2 pi sigma))
};

struct DensityTreatment {
  std::string diffusion = "fourtakas";  // none | molteni | fourtakas (delta-SPH)
  double delta = 0.1;                   // delta-SPH coefficient
  bool shepard = false;                 // Shepard density re-initialisation (seed eq. 20)
  int shepard_interval = 20;            // ... every N steps
};

// Particle shifting (docs/sph.md, "Particle shifting").
struct Shifting {
  std::string model = "none";  // none | fickian (Lind et al. 2012)
  double coefficient = 4.0;    // A of D = A h U_max dt
};

struct Config {
  std::string scheme = "weakly_compressible";  // | incompressible (docs/sph.md) | multi_material
  double pressure_tolerance = 1e-6;            // incompressible: relative residual of the solve
  int pressure_iterations = 1000;              // incompressible: BiCGSTAB iterations at most
  std::string viscosity_integration = "explicit";  // | implicit (incompressible only)
  int viscosity_iterations = 10;                   // implicit: Picard iterations at most
  double spacing = 0.0;                            // initial particle spacing dp [m]
  double smoothing_ratio = 1.5;                    // h / dp (docs/sph.md, "Choice of h")
  bool variable_smoothing_length =
      false;  // h_i = smoothing_ratio (m_i / rho_i)^(1/d) (docs/sph.md)
  std::string kernel = "wendland_c2";
  std::string gradient_kernel;             // empty: the same as kernel
  std::string equation_of_state = "tait";  // tait | linear
  double tait_gamma = 7.0;
  std::optional<double> sound_speed;   // c0 [m/s]; when absent, mach_factor * max_velocity
  std::optional<double> max_velocity;  // [m/s]; when absent, 2 sqrt(|g| H) of the fluid
  double mach_factor = 10.0;
  std::optional<double> flow_length;  // L [m] of the viscous criterion; absent: fluid's narrowest
  double artificial_viscosity = 0.0;  // Monaghan alpha; 0: off
  bool laminar_viscosity = true;      // laminar viscous term with the fluid's viscosity
  std::string viscous_operator = "auto";      // auto | morris | stress (seed eqs. 14-15)
  std::string viscosity_mean = "arithmetic";  // arithmetic | harmonic, pair mean (Morris term)
  bool corrected_velocity_gradient = true;    // kernel-gradient-corrected shear rate
  DensityTreatment density;
  Shifting shifting;
  std::optional<int> wall_layers;       // when absent, enough layers to cover the kernel support
  bool negative_wall_pressure = false;  // false: p_w = max(p_w, 0) (free-surface flows)
  std::string wall_velocity = "adami";  // adami | extrapolated: the no-slip ghost velocity
  TimeStepFactors time_step;
  int sort_interval = 20;  // re-sort particles by cell every N steps
  // sph.lattice: particles on rings about this point's z-parallel axis (geometry/lattice.hpp);
  // absent: the Cartesian lattice.
  std::optional<Vec3> polar_centre;
  bool golden_rings = false;  // sph.lattice.rings: golden (geometry/lattice.hpp)
  // scheme: multi_material (docs/multi-material-sph.md): its materials and settings.
  MultiMaterialSettings multi_material;

  double smoothing_length() const { return smoothing_ratio * spacing; }
};

}  // namespace partimix::sph
