#include "io/truck_drum_section.hpp"

#include <numbers>
#include <stdexcept>

#include <fmt/format.h>

#include "geometry/truck_drum_shape.hpp"

namespace partimix::io {
namespace {

constexpr double kRadiansPerDegree = std::numbers::pi / 180.0;

// The blades: height and thickness [m], helix angle and the three segments' offset angles [deg].
void read_blades(Reader& item, geometry::TruckDrumParameters& p) {
  Reader blades = item.map("blades");
  p.blade_height = blades.required<double>("height", kPositive);
  p.blade_thickness = blades.required<double>("thickness", kPositive);
  const double helix = blades.required<double>("helix_angle", kPositive);
  if (!(helix < 90.0))
    throw blades.error("helix_angle", "must lie in (0, 90) degrees");
  p.helix_angle = helix * kRadiansPerDegree;
  const Vec3 offsets = blades.vector("offset_angles", 3);
  for (int s = 0; s < 3; ++s)
    p.offset_angles[s] = offsets[s] * kRadiansPerDegree;
  blades.done();
}

}  // namespace

std::shared_ptr<const geometry::Shape> read_truck_drum(Reader& item, int dimensions) {
  if (dimensions != 3)
    throw item.error("shape",
                     fmt::format("truck_drum needs dimensions: 3, this case has {}", dimensions));
  const Vec3 point = item.vector("axis_point", 3);
  const Vec3 axis = item.vector("axis", 3);
  if (axis.norm() == 0.0)
    throw item.error("axis", "the axis must not be the zero vector");
  geometry::TruckDrumParameters p;
  p.head_radius = item.required<double>("head_radius", kPositive);
  p.front_length = item.required<double>("front_length", kPositive);
  p.radius = item.required<double>("radius", kPositive);
  p.cylinder_length = item.required<double>("cylinder_length", kPositive);
  p.rear_length = item.required<double>("rear_length", kPositive);
  p.opening_radius = item.required<double>("opening_radius", kPositive);
  read_blades(item, p);
  const int divisions = item.optional<int>("divisions", 96, at_least(12));
  if (divisions > 4096)
    throw item.error("divisions", "must be at most 4096");
  try {
    return std::make_shared<geometry::TruckDrumShape>(p, point, axis, divisions);
  } catch (const std::invalid_argument& error) {
    throw item.error("shape", fmt::format("this truck drum cannot be built: {}", error.what()));
  }
}

}  // namespace partimix::io
