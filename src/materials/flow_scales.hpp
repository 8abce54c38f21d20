#pragma once
// The scales of a fluid for Reynolds numbers (docs/power.md, "Reynolds number"): its density,
// the consistency K_s and the flow index n of Re = rho N^(2-n) d^2 / (K_s k^(n-1)). A Newtonian
// fluid has K_s = mu and n = 1; a power-law or Herschel-Bulkley fluid its own K and n. Other
// models have no single K and n, so they have no flow scales.
#include <optional>

#include "materials/rheology.hpp"

namespace partimix::materials {

struct FlowScales {
  double density = 0.0;      // rho [kg/m^3]
  double consistency = 0.0;  // K_s [Pa s^n]
  double flow_index = 1.0;   // n [-]
};

inline std::optional<FlowScales> flow_scales(double density, const RheologyConfig& rheology) {
  if (rheology.model == "newtonian")
    return FlowScales{density, rheology.viscosity, 1.0};
  if (rheology.model == "power_law" || rheology.model == "herschel_bulkley")
    return FlowScales{density, rheology.consistency, rheology.flow_index};
  return std::nullopt;
}

}  // namespace partimix::materials
