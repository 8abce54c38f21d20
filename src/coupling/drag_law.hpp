#pragma once
// The drag of the fluid on a grain (docs/cfd-dem.md, "The forces on a grain"):
// f_d = k V_i (u_i - v_i), with k [kg/(m³ s)] the law's coefficient per unit grain volume
// (Gidaspow's β / (1 - ε)). Laws are chosen by name (`coupling.drag`): gidaspow, gidaspow_blended,
// di_felice. Each is written through C_d Re_p, which stays finite as the slip vanishes.
#include <memory>

#include "core/registry.hpp"

namespace partimix::coupling {

struct DragState {
  double void_fraction;  // ε at the grain
  double slip;           // |u_i - v_i| [m/s]
  double diameter;       // d [m]
  double density;        // the fluid's ρ [kg/m³]
  double viscosity;      // the fluid's μ (or apparent η) [Pa s]
};

class DragLaw {
 public:
  virtual ~DragLaw() = default;
  virtual double coefficient(const DragState& state) const = 0;
};

const Registry<DragLaw>& drag_law_registry();

// Re_p = ε ρ |u_s| d / μ.
inline double particle_reynolds(const DragState& s) {
  return s.void_fraction * s.density * s.slip * s.diameter / s.viscosity;
}

// C_d Re_p of a sphere after Schiller & Naumann (1933): 24 (1 + 0.15 Re^0.687) below Re = 1000,
// 0.44 Re above.
double schiller_naumann_cd_re(double re);

}  // namespace partimix::coupling
