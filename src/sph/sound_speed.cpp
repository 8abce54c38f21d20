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

double resolve_sound_speed(const Config& config, const ParticleStore& store,
                           const Vec3& hydrostatic_gravity) {
  if (config.sound_speed)
    return *config.sound_speed;
  double max_velocity = config.max_velocity.value_or(0.0);
  if (!config.max_velocity) {
    const double height = fluid_height(store, hydrostatic_gravity, config.spacing);
    max_velocity = 2.0 * std::sqrt(hydrostatic_gravity.norm() * height);
  }
  if (!(max_velocity > 0.0)) {
    throw InputError(InputLocation{"", 0, 0, "sph.max_velocity"},
                     "cannot estimate the flow speed without gravity across the fluid; give "
                     "sph.max_velocity or sph.sound_speed");
  }
  return config.mach_factor * max_velocity;
}

}  // namespace partimix::sph
