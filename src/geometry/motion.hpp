#pragma once
// Prescribed rigid-body motions (docs/motions.md; the seed's eqs. 21-22): where a body is at
// time t relative to where it was at t = 0. Angles are counter-clockwise positive about the
// motion's axis (right-hand rule), as in the seed; speeds are given in rpm.
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "core/registry.hpp"
#include "core/vec.hpp"

namespace partimix::geometry {

// The pose of a body at one instant: a point X of the body at t = 0 is at place(X), moving
// with velocity_at(place(X)).
struct RigidPose {
  Vec3 start_origin = Vec3::Zero();  // a reference point of the body at t = 0
  Vec3 origin = Vec3::Zero();        // that point now
  Mat3 rotation = Mat3::Identity();  // orientation now relative to t = 0
  Vec3 velocity = Vec3::Zero();      // of the reference point
  Vec3 angular_velocity = Vec3::Zero();

  Vec3 place(const Vec3& start) const { return origin + rotation * (start - start_origin); }
  Vec3 velocity_at(const Vec3& x) const { return velocity + angular_velocity.cross(x - origin); }
};

// A change of a rotation's speed: from `time` on it turns at `rpm`, reached over the ramp time.
struct SpeedChange {
  double time = 0.0;  // [s]
  double rpm = 0.0;
};

// The settings of every motion kind, as read from a case file's `motion:` map.
struct MotionConfig {
  std::string type = "fixed";      // fixed | rotation | planetary | translation | sliding
  Vec3 axis = Vec3::UnitZ();       // unit axis of rotation (and of revolution)
  Vec3 axis_point = Vec3::Zero();  // rotation: a point of the axis; planetary: the body's own axis
  double rpm = 0.0;                // rotation: N; planetary: spin N_R about the own axis
  Vec3 centre = Vec3::Zero();      // planetary: a point of the revolution (vessel) axis
  double revolution_rpm = 0.0;     // planetary: N_G about the revolution axis
  double ramp_time = 0.0;          // smooth start-up over this time [s]; 0: none
  std::vector<SpeedChange> schedule;  // rotation: later speeds, at increasing times after 0
  Vec3 velocity = Vec3::Zero();       // translation, sliding: the constant velocity [m/s]
  double start = 0.0;                 // translation: moves from this time [s]
  double stop = std::numeric_limits<double>::infinity();  // translation: until this time [s]
};

class Motion {
 public:
  virtual ~Motion() = default;
  virtual RigidPose pose(double time) const = 0;
  virtual bool moves() const { return true; }
};

// Motions by name, built from the configuration.
const Registry<Motion, const MotionConfig&>& motion_registry();

}  // namespace partimix::geometry
