#pragma once
// The incompressible scheme's closure (docs/sph.md, "Incompressible SPH"): the density is rho0
// whatever the pressure, which the pressure Poisson equation sets; no pressure follows from a
// density, so pressure() is 0 (the scheme never asks it).
#include "sph/equation_of_state.hpp"

namespace partimix::sph {

class IncompressibleEos final : public EquationOfState {
 public:
  explicit IncompressibleEos(double reference_density) : rho0_(reference_density) {}
  double pressure(double /*density*/) const override { return 0.0; }
  double density(double /*pressure*/) const override { return rho0_; }

 private:
  double rho0_;
};

}  // namespace partimix::sph
