#pragma once
// A material of the multi-material SPH scheme ready to use (docs/multi-material-sph.md, "The
// scheme"): its specification, its equation of state, and its initial density. The Tait law
// gives the pressure above the ambient (it is 0 at the reference density), the gas laws the
// absolute pressure; absolute_pressure() adds the ambient to the first.
#include <memory>
#include <vector>

#include "materials/thermal_eos.hpp"
#include "sph/multi_material/material_spec.hpp"

namespace partimix::sph {

class Material {
 public:
  // Throws InputError at key sph.materials[index] when the initial state cannot be met (no
  // density gives the initial pressure).
  Material(const MaterialSpec& spec, double ambient_pressure, std::size_t index);

  const MaterialSpec& spec() const { return spec_; }
  const materials::ThermalEquationOfState& eos() const { return *eos_; }
  double initial_density() const { return initial_density_; }
  double absolute_pressure(double density, double temperature) const {
    return eos_->pressure(density, temperature) + pressure_offset_;
  }

 private:
  MaterialSpec spec_;
  std::shared_ptr<const materials::ThermalEquationOfState> eos_;
  double pressure_offset_;
  double initial_density_;
};

std::vector<Material> build_materials(const MultiMaterialSettings& settings);

}  // namespace partimix::sph
