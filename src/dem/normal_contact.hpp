#pragma once
// Normal contact laws of DEM, chosen by name (docs/dem.md, "Normal force"): hertz (Hertz with
// the damping of Tsuji et al. 1992 and Antypov and Elliott 2011) and linear (Cundall and Strack
// 1979 spring-dashpot).
#include "core/registry.hpp"
#include "dem/pair_properties.hpp"

namespace partimix::dem {

struct NormalResponse {
  double force = 0.0;  // on particle i along n [N] (positive: repulsive)
  // The tangent normal stiffness dF_n/d(overlap) of the elastic part [N/m]: the rolling spring
  // of the elastic-plastic rolling resistance is made from it.
  double normal_stiffness = 0.0;
  // The stiffness k_t of the tangential spring [N/m] and its damping coefficient c_t [N s/m]
  // (docs/dem.md, "Tangential force").
  double tangential_stiffness = 0.0;
  double tangential_damping = 0.0;
};

class NormalContactLaw {
 public:
  virtual ~NormalContactLaw() = default;
  // The law at overlap > 0 for the normal relative velocity u_n = v_c . n of the contact point
  // (negative while the pair approaches): all of it in one call, which shares the square roots.
  virtual NormalResponse respond(const PairProperties& pair, double overlap,
                                 double normal_velocity) const = 0;
};

struct NormalLawParameters {
  double stiffness = 0.0;  // k_n of the linear law [N/m]
};

const Registry<NormalContactLaw, const NormalLawParameters&>& normal_contact_registry();

}  // namespace partimix::dem
