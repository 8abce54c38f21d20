#pragma once
// Hyperbolic-shaped kernel (Yang, Peng and Liu 2014; the seed's eq. 12), support 2h:
// f(q) = q^3 - 6 q + 6 for q < 1, (2 - q)^3 for 1 <= q < 2. Its slope does not vanish at q = 0,
// which keeps particles from pairing under tension (the seed uses it for the gradient only).
// sigma_2 = 1 / (3 pi) (as printed in the seed), sigma_3 = 15 / (62 pi) (from int W dV = 1).
#include "sph/kernel.hpp"

namespace partimix::sph {

class Hyperbolic final : public Kernel {
 public:
  double shape(double q) const override;
  double shape_derivative(double q) const override;
  double normalisation(int dimensions) const override;
};

}  // namespace partimix::sph
