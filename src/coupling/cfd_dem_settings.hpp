#pragma once
// What a `couplings: [{type: cfd_dem, ...}]` item says (docs/case-reference.md, "couplings";
// docs/cfd-dem.md).
#include <optional>
#include <string>

namespace partimix::coupling {

// The pressure's force on a grain (docs/cfd-dem.md, "The forces on a grain"): -V_i ∇p (model A,
// momentum kept), the hydrostatic buoyancy -ρ V_i g alone (seed 004's F_o), or none.
enum class PressureForce { gradient, buoyancy, none };

struct CfdDemSettings {
  std::string drag = "gidaspow";  // a name of drag_law_registry()
  PressureForce pressure_force = PressureForce::gradient;
  bool divided = false;                 // the divided mapping, not the kernel (kernel_weights.hpp)
  std::optional<double> kernel_radius;  // b [m]; none: max(2 d_max, 1.5 h_max)
  double min_void_fraction = 0.3;
  // false: one-way, the grains feel the fluid but the fluid neither sees their volume (ε = 1)
  // nor gets their drag back.
  bool two_way = true;
  // The virtual-mass force C_vm ρ V_i (d(u - v)/dt)_i on each grain (seed 004's F_x), lagged by a
  // step; stable while C_vm ρ / ρ_p < 1.
  bool virtual_mass = false;
  double virtual_mass_coefficient = 0.5;
  int grain_sub_steps = 1;  // the DEM's steps per fluid step (time.sub_steps.dem)
};

}  // namespace partimix::coupling
