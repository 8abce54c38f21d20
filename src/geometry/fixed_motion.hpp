#pragma once
// A body that does not move.
#include "geometry/motion.hpp"

namespace partimix::geometry {

class FixedMotion final : public Motion {
 public:
  RigidPose pose(double) const override { return {}; }
  bool moves() const override { return false; }
};

}  // namespace partimix::geometry
