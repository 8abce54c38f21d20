#include "geometry/motion.hpp"

#include "geometry/fixed_motion.hpp"
#include "geometry/planetary_motion.hpp"
#include "geometry/rotation_motion.hpp"
#include "geometry/sliding_motion.hpp"
#include "geometry/translation_motion.hpp"

namespace partimix::geometry {

const Registry<Motion, const MotionConfig&>& motion_registry() {
  static const Registry<Motion, const MotionConfig&> registry = [] {
    Registry<Motion, const MotionConfig&> r;
    r.add("fixed", [](const MotionConfig&) { return std::make_unique<FixedMotion>(); });
    r.add("rotation", [](const MotionConfig& c) {
      return std::make_unique<RotationMotion>(c.axis_point, c.axis, c.rpm, c.ramp_time, c.schedule);
    });
    r.add("planetary", [](const MotionConfig& c) {
      return std::make_unique<PlanetaryMotion>(c.axis_point, c.centre, c.axis, c.rpm,
                                               c.revolution_rpm, c.ramp_time);
    });
    r.add("translation", [](const MotionConfig& c) {
      return std::make_unique<TranslationMotion>(c.velocity, c.start, c.stop);
    });
    r.add("sliding", [](const MotionConfig& c) {
      return std::make_unique<SlidingMotion>(c.velocity, c.ramp_time);
    });
    return r;
  }();
  return registry;
}

}  // namespace partimix::geometry
