#include "coupling/drag_laws/gidaspow.hpp"

#include <cmath>

namespace partimix::coupling {

double ergun_coefficient(const DragState& s) {
  const double eps = s.void_fraction;
  return 150.0 * (1.0 - eps) * s.viscosity / (eps * s.diameter * s.diameter) +
         1.75 * s.density * s.slip / s.diameter;
}

double wen_yu_coefficient(const DragState& s) {
  const double cd_re = schiller_naumann_cd_re(particle_reynolds(s));
  return 0.75 * cd_re * s.viscosity / (s.diameter * s.diameter) * std::pow(s.void_fraction, -2.65);
}

double Gidaspow::coefficient(const DragState& s) const {
  return s.void_fraction < 0.8 ? ergun_coefficient(s) : wen_yu_coefficient(s);
}

double GidaspowBlended::coefficient(const DragState& s) const {
  const double phi = 0.5 + std::atan(262.5 * ((1.0 - s.void_fraction) - 0.2)) / M_PI;
  return phi * ergun_coefficient(s) + (1.0 - phi) * wen_yu_coefficient(s);
}

}  // namespace partimix::coupling
