#include "sph/rheology/newtonian.hpp"

namespace partimix::sph {

Newtonian::Newtonian(double viscosity) : viscosity_(viscosity) {}

double Newtonian::apparent_viscosity(double) const {
  return viscosity_;
}

}  // namespace partimix::sph
