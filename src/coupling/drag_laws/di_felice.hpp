#pragma once
// Di Felice's drag (Di Felice 1994, Int. J. Multiphase Flow 20, 153; docs/cfd-dem.md):
// f_d = (1/2) C_d ρ (π d² / 4) ε² |u_s| u_s ε^-χ with Dallavalle's C_d = (0.63 + 4.8 / √Re_p)²
// and χ = 3.7 - 0.65 exp(-(1.5 - log10 Re_p)² / 2), so k = (3/4) C_d Re_p μ ε^(1-χ) / d², with
// C_d Re_p = (0.63 √Re_p + 4.8)².
#include "coupling/drag_law.hpp"

namespace partimix::coupling {

class DiFelice : public DragLaw {
 public:
  double coefficient(const DragState& s) const override;
};

}  // namespace partimix::coupling
