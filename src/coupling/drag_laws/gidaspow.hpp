#pragma once
// Gidaspow's drag (Gidaspow 1994, ch. 5; seed 004's formulas; docs/cfd-dem.md): Ergun's equation
// below ε = 0.8, Wen & Yu's above, and their blend after Lu & Gidaspow (2003).
#include "coupling/drag_law.hpp"

namespace partimix::coupling {

// k = 150 (1 - ε) μ / (ε d²) + 1.75 ρ |u_s| / d.
double ergun_coefficient(const DragState& s);
// k = (3/4) C_d Re_p μ / d² ε^-2.65 (= (3/4) C_d ε ρ |u_s| / d ε^-2.65).
double wen_yu_coefficient(const DragState& s);

class Gidaspow : public DragLaw {
 public:
  double coefficient(const DragState& s) const override;
};

// φ k_Ergun + (1 - φ) k_WenYu, φ = 1/2 + arctan(262.5 ((1 - ε) - 0.2)) / π.
class GidaspowBlended : public DragLaw {
 public:
  double coefficient(const DragState& s) const override;
};

}  // namespace partimix::coupling
