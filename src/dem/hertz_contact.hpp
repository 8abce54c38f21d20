#pragma once
// Hertz normal force with viscous damping (docs/dem.md, "Normal force"):
// F_n = k_H d^(3/2) - sqrt(5) beta sqrt(m* k_H) d^(1/4) u_n, k_H = (4/3) E* sqrt(R*); the
// coefficient sqrt(5) beta gives restitution e exactly (Antypov and Elliott 2011).
// Tangential stiffness after Mindlin (1949).
#include "dem/normal_contact.hpp"

namespace partimix::dem {

class HertzContact final : public NormalContactLaw {
 public:
  // With the contact radius a = sqrt(R* d): S_n = 2 E* a, F_n = (2/3) S_n d
  // - 2 sqrt(5/6) beta sqrt(m* S_n) u_n (the form above), and Mindlin's k_t = 8 G* a.
  NormalResponse respond(const PairProperties& pair, double overlap,
                         double normal_velocity) const override;
};

}  // namespace partimix::dem
