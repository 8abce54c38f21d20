#include "materials/rheology/newtonian.hpp"

namespace partimix::materials {

Newtonian::Newtonian(double viscosity) : viscosity_(viscosity) {}

double Newtonian::apparent_viscosity(double) const {
  return viscosity_;
}

}  // namespace partimix::materials
