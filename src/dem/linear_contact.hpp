#pragma once
// Linear spring-dashpot normal force (docs/dem.md, "Normal force"; Cundall and Strack 1979):
// F_n = k_n d - 2 beta sqrt(m* k_n) u_n, restitution e exactly.
#include "dem/normal_contact.hpp"

namespace partimix::dem {

class LinearContact final : public NormalContactLaw {
 public:
  explicit LinearContact(double stiffness) : stiffness_(stiffness) {}
  // k_t = (2/7) k_n (Silbert et al. 2001; LIGGGHTS's hooke default): the tangential and normal
  // oscillations of a sphere then have one period.
  NormalResponse respond(const PairProperties& pair, double overlap,
                         double normal_velocity) const override;

 private:
  double stiffness_;  // k_n [N/m]
};

}  // namespace partimix::dem
