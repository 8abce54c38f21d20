#pragma once
// Translation at a constant velocity between two times (docs/motions.md): a gate lifted or a
// piston pushed. At rest before `start` and after `stop`, the body keeps its place there, so
// its position is continuous and its velocity jumps at both times.
#include "geometry/motion.hpp"

namespace partimix::geometry {

class TranslationMotion final : public Motion {
 public:
  // Moves at `velocity` [m/s] for start <= t < stop [s]; stop may be infinite. Throws
  // std::invalid_argument unless start <= stop.
  TranslationMotion(const Vec3& velocity, double start, double stop);
  RigidPose pose(double time) const override;

 private:
  Vec3 velocity_;
  double start_;
  double stop_;
};

}  // namespace partimix::geometry
