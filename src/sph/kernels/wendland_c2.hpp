#pragma once
// Wendland C2 kernel (Wendland 1995; Dehnen and Aly 2012, table 1), support 2h:
// f(q) = (1 - q/2)^4 (2 q + 1) for q < 2. sigma_2 = 7 / (4 pi), sigma_3 = 21 / (16 pi).
#include "sph/kernel.hpp"

namespace partimix::sph {

class WendlandC2 final : public Kernel {
 public:
  double shape(double q) const override;
  double shape_derivative(double q) const override;
  double normalisation(int dimensions) const override;
};

}  // namespace partimix::sph
