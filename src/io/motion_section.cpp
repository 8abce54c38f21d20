#include "io/motion_section.hpp"

#include <optional>

namespace partimix::io {

namespace {

// The rotation axis: z in 2D (the plane's normal); in 3D any non-zero vector, normalised.
Vec3 read_axis(Reader& section, int dimensions) {
  if (dimensions == 2)
    return Vec3::UnitZ();
  const Vec3 axis = section.vector("axis", 3, Vec3::UnitZ());
  if (axis.norm() == 0.0)
    throw section.error("axis", "the axis must not be the zero vector");
  return axis.normalized();
}

// translation: the velocity, and the times it starts and stops (never, for `auto`).
void read_translation(Reader& section, geometry::MotionConfig& motion, int dimensions) {
  motion.velocity = section.vector("velocity", dimensions);
  motion.start = section.optional<double>("start", motion.start, kNonNegative);
  if (const std::optional<double> stop = section.automatic<double>("stop", kNonNegative)) {
    if (!(*stop > motion.start))
      throw section.error("stop", "stop must be later than start");
    motion.stop = *stop;
  }
}

// rotation: later speeds, each {time, rpm} at a time after the one before (and after 0).
void read_schedule(Reader& section, geometry::MotionConfig& motion) {
  double previous = 0.0;
  for (Reader& item : section.optional_list("schedule")) {
    geometry::SpeedChange change;
    change.time = item.required<double>("time", kPositive);
    if (!(change.time > previous))
      throw item.error("time", "the schedule's times must increase");
    change.rpm = item.required<double>("rpm");
    item.done();
    motion.schedule.push_back(change);
    previous = change.time;
  }
}

}  // namespace

geometry::MotionConfig read_motion(Reader& item, int dimensions) {
  Reader section = item.optional_map("motion");
  geometry::MotionConfig motion;
  motion.type = section.choice("type", motion.type,
                               {"fixed", "rotation", "planetary", "translation", "sliding"});
  if (motion.type == "rotation" || motion.type == "planetary") {
    motion.axis = read_axis(section, dimensions);
    motion.axis_point = section.vector("axis_point", dimensions, Vec3::Zero());
    motion.rpm = section.required<double>("rpm");
    motion.ramp_time = section.optional<double>("ramp_time", 0.0, kNonNegative);
  }
  if (motion.type == "rotation")
    read_schedule(section, motion);
  if (motion.type == "planetary") {
    motion.centre = section.vector("centre", dimensions, Vec3::Zero());
    motion.revolution_rpm = section.required<double>("revolution_rpm");
  }
  if (motion.type == "translation")
    read_translation(section, motion, dimensions);
  if (motion.type == "sliding") {
    motion.velocity = section.vector("velocity", dimensions);
    motion.ramp_time = section.optional<double>("ramp_time", 0.0, kNonNegative);
  }
  section.done();
  return motion;
}

}  // namespace partimix::io
