#include "sph/sound_speed.hpp"

#include "core/error.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace partimix::sph {

double fluid_height(const ParticleStore& store, const Vec3& gravity, double spacing) {
  const double g = gravity.norm();
  if (g == 0.0)
    return 0.0;
  const Vec3 up = -gravity / g;
  double lowest = std::numeric_limits<double>::max();
  double highest = std::numeric_limits<double>::lowest();
  for (std::size_t i = 0; i < store.size(); ++i) {
    if (!store.is_fluid(i))
      continue;
    const double height = up.dot(store.position()[i]);
    lowest = std::min(lowest, height);
    highest = std::max(highest, height);
  }
  return highest >= lowest ? highest - lowest + spacing : 0.0;
}

double fluid_narrowest_extent(const ParticleStore& store, int dimensions, double spacing) {
  Vec3 lowest = Vec3::Constant(std::numeric_limits<double>::max());
  Vec3 highest = Vec3::Constant(std::numeric_limits<double>::lowest());
  for (std::size_t i = 0; i < store.size(); ++i) {
    if (!store.is_fluid(i))
      continue;
    lowest = lowest.cwiseMin(store.position()[i]);
    highest = highest.cwiseMax(store.position()[i]);
  }
  double narrowest = std::numeric_limits<double>::max();
  for (int axis = 0; axis < dimensions; ++axis)
    narrowest = std::min(narrowest, highest[axis] - lowest[axis] + spacing);
  return narrowest > 0.0 && narrowest < std::numeric_limits<double>::max() ? narrowest : spacing;
}

namespace {

// nu U / L [m^2/s^2] of the viscous criterion, with the apparent viscosity at U / L.
double viscous_scale(const Config& config, const ParticleStore& store, double max_velocity,
                     const materials::BoundedRheology& rheology, double density, int dimensions) {
  const double length =
      config.flow_length.value_or(fluid_narrowest_extent(store, dimensions, config.spacing));
  const double shear_rate = max_velocity / length;
  return rheology.viscosity(shear_rate) / density * shear_rate;
}

}  // namespace

double estimated_max_velocity(const Config& config, const ParticleStore& store,
                              const Vec3& hydrostatic_gravity) {
  const double height = fluid_height(store, hydrostatic_gravity, config.spacing);
  const double max_velocity =
      config.max_velocity.value_or(2.0 * std::sqrt(hydrostatic_gravity.norm() * height));
  if (!(max_velocity > 0.0)) {
    throw InputError(InputLocation{"", 0, 0, "sph.max_velocity"},
                     "cannot estimate the flow speed without gravity across the fluid; give "
                     "sph.max_velocity or sph.sound_speed");
  }
  return max_velocity;
}

double resolve_sound_speed(const Config& config, const ParticleStore& store,
                           const Vec3& hydrostatic_gravity,
                           const materials::BoundedRheology& rheology, double density,
                           int dimensions) {
  if (config.sound_speed)
    return *config.sound_speed;
  const double gravity_scale =
      hydrostatic_gravity.norm() * fluid_height(store, hydrostatic_gravity, config.spacing);
  const double max_velocity = estimated_max_velocity(config, store, hydrostatic_gravity);
  const double viscous = viscous_scale(config, store, max_velocity, rheology, density, dimensions);
  const double squared = std::max({max_velocity * max_velocity, viscous, gravity_scale});
  return config.mach_factor * std::sqrt(squared);
}

}  // namespace partimix::sph
