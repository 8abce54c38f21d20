#include "geometry/translation_motion.hpp"

#include <algorithm>
#include <stdexcept>

namespace partimix::geometry {

TranslationMotion::TranslationMotion(const Vec3& velocity, double start, double stop)
    : velocity_(velocity), start_(start), stop_(stop) {
  if (!(start <= stop))
    throw std::invalid_argument("translation: stop must not come before start");
}

// o(t) = o0 + v (clamp(t, start, stop) - start), with o0 the origin.
RigidPose TranslationMotion::pose(double time) const {
  RigidPose pose;
  pose.origin = velocity_ * (std::clamp(time, start_, stop_) - start_);
  if (time >= start_ && time < stop_)
    pose.velocity = velocity_;
  return pose;
}

}  // namespace partimix::geometry
