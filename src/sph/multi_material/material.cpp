#include "sph/multi_material/material.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include <fmt/format.h>

#include "core/error.hpp"

namespace partimix::sph {
namespace {

// The density at which the material's absolute pressure is `target` at temperature T, by
// Newton's method from the ideal gas's (or the reference) density; nullopt when it does not
// converge to a positive density.
std::optional<double> density_at(const Material& material, double target, double temperature,
                                 double guess) {
  double density = guess;
  for (int iteration = 0; iteration < 100; ++iteration) {
    const double residual = material.absolute_pressure(density, temperature) - target;
    const double slope = material.eos().pressure_density_derivative(density, temperature);
    if (!(slope > 0.0))
      return std::nullopt;
    const double next =
        std::max(0.5 * density, std::min(2.0 * density, density - residual / slope));
    if (std::abs(next - density) <= 1e-13 * density)
      return next;
    density = next;
  }
  return std::nullopt;
}

double first_guess(const MaterialSpec& spec, double pressure) {
  if (spec.eos.model == "tait")
    return spec.eos.reference_density;
  return pressure * spec.eos.molar_mass / (materials::kMolarGasConstant * spec.temperature);
}

}  // namespace

Material::Material(const MaterialSpec& spec, double ambient_pressure, std::size_t index)
    : spec_(spec),
      eos_(materials::thermal_eos_registry().create(spec.eos.model, spec.eos)),
      pressure_offset_(spec.eos.model == "tait" ? ambient_pressure : 0.0),
      initial_density_(0.0) {
  const std::string key = fmt::format("sph.materials[{}]", index);
  if (!eos_)
    throw InputError(InputLocation{"", 0, 0, key + ".eos.model"},
                     "unknown equation of state '" + spec.eos.model + "'");
  if (spec.density) {
    initial_density_ = *spec.density;
  } else if (spec.pressure) {
    const auto density =
        density_at(*this, *spec.pressure, spec.temperature, first_guess(spec, *spec.pressure));
    if (!density) {
      throw InputError(
          InputLocation{"", 0, 0, key + ".pressure"},
          fmt::format("no density gives {:.6g} Pa at {:.6g} K", *spec.pressure, spec.temperature));
    }
    initial_density_ = *density;
  } else {
    initial_density_ = spec.eos.reference_density;
  }
}

std::vector<Material> build_materials(const MultiMaterialSettings& settings) {
  std::vector<Material> materials;
  for (std::size_t m = 0; m < settings.materials.size(); ++m)
    materials.emplace_back(settings.materials[m], settings.ambient.pressure, m);
  return materials;
}

}  // namespace partimix::sph
