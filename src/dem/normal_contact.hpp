#pragma once
// Normal contact laws of DEM, chosen by name (docs/dem.md, "Normal force"): hertz (Hertz with
// the damping of Tsuji et al. 1992 and Antypov and Elliott 2011) and linear (Cundall and Strack
// 1979 spring-dashpot).
#include "core/registry.hpp"
#include "dem/pair_properties.hpp"

namespace partimix::dem {

class NormalContactLaw {
 public:
  virtual ~NormalContactLaw() = default;
  // The normal force on particle i along n (positive: repulsive) at overlap > 0, for the normal
  // relative velocity u_n = v_c . n of the contact point (negative while the pair approaches).
  virtual double force(const PairProperties& pair, double overlap,
                       double normal_velocity) const = 0;
  // The tangent normal stiffness dF_n/d(overlap) of the elastic part [N/m]: the rolling spring
  // of the elastic-plastic rolling resistance is made from it.
  virtual double normal_stiffness(const PairProperties& pair, double overlap) const = 0;
  // The stiffness k_t of the tangential spring [N/m] (docs/dem.md, "Tangential force").
  virtual double tangential_stiffness(const PairProperties& pair, double overlap) const = 0;
};

struct NormalLawParameters {
  double stiffness = 0.0;  // k_n of the linear law [N/m]
};

const Registry<NormalContactLaw, const NormalLawParameters&>& normal_contact_registry();

}  // namespace partimix::dem
