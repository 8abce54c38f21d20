#include "coupling/drag_laws/di_felice.hpp"

#include <cmath>

namespace partimix::coupling {

double DiFelice::coefficient(const DragState& s) const {
  const double re = particle_reynolds(s);
  const double root = 0.63 * std::sqrt(re) + 4.8;
  const double log_re = std::log10(re);  // -inf at zero slip, where χ = 3.7
  const double chi = 3.7 - 0.65 * std::exp(-0.5 * (1.5 - log_re) * (1.5 - log_re));
  return 0.75 * root * root * s.viscosity / (s.diameter * s.diameter) *
         std::pow(s.void_fraction, 1.0 - chi);
}

}  // namespace partimix::coupling
