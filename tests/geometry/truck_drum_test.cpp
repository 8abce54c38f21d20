// The truck drum's geometry in its own frame (docs/truck-drum.md, "The drum in its own frame"):
// the shell's signed distance against the closed forms of each part (the cylinder's ρ - R, the
// cones' distance along their normals, the head's and the opening's planes), the blades' helix
// angle measured from points of the generated blade on the shell against β, and the blade's
// distance across, inside and beyond its strip. Tolerances: 1e-12 m for the exact distances,
// 1e-7 rad for the angle measured by central differences, 2e-3 of the offset for the first-order
// distance across a blade.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "eight_cubic_metre_drum.hpp"
#include "geometry/truck_drum.hpp"

namespace partimix::geometry {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

Vec3 at(double z, double theta, double rho) {
  return {rho * std::cos(theta), rho * std::sin(theta), z};
}

TEST(TruckDrum, ShellDistanceFollowsEachPartsClosedForm) {
  const TruckDrumGeometry drum(eight_cubic_metre_drum());
  EXPECT_NEAR(drum.length(), 5.4, 1e-15);
  // Cylinder: ρ - R, inside and out, at any angle.
  for (const double rho : {1.0, 1.1, 1.2})
    EXPECT_NEAR(drum.shell_distance(at(2.6, 0.3, rho)), rho - 1.15, 1e-12) << rho;
  // Each cone: a point d along the outward normal from a point of its generator.
  for (const int s : {0, 2}) {
    const double z0 = drum.segment_start(s) + 0.4;
    const double r0 = drum.radius_at(z0);
    const double slope = drum.slope(s);
    const double norm = std::sqrt(1.0 + slope * slope);
    for (const double d : {-0.05, 0.02, 0.1}) {
      const Vec3 x = at(z0 - d * slope / norm, 1.7, r0 + d / norm);
      EXPECT_NEAR(drum.shell_distance(x), d, 1e-12) << s << " " << d;
    }
  }
  // The head and the opening: planes near the axis.
  EXPECT_NEAR(drum.shell_distance(at(-0.07, 0.0, 0.2)), 0.07, 1e-12);
  EXPECT_NEAR(drum.shell_distance(at(0.05, 0.0, 0.2)), -0.05, 1e-12);
  EXPECT_NEAR(drum.shell_distance(at(5.45, 2.0, 0.1)), 0.05, 1e-12);
}

// The blade's curve on the shell, P(z) = (r cos θ_s, r sin θ_s, z), against the generatrix
// G = (r' cos θ_s, r' sin θ_s, 1): their angle is β on every segment.
TEST(TruckDrum, BladesMakeTheHelixAngleWithTheGeneratrix) {
  const TruckDrumGeometry drum(eight_cubic_metre_drum());
  const double h = 1e-5;
  for (int s = 0; s < 3; ++s)
    for (const double along : {0.3, 0.9, 1.5}) {
      const double z = drum.segment_start(s) + along;
      const auto point = [&](double zz) {
        return at(zz, drum.blade_angle(s, zz), drum.radius_at(zz));
      };
      const Vec3 tangent = (point(z + h) - point(z - h)).normalized();
      const double theta = drum.blade_angle(s, z);
      const Vec3 generatrix =
          Vec3(drum.slope(s) * std::cos(theta), drum.slope(s) * std::sin(theta), 1.0).normalized();
      const double angle = std::acos(std::clamp(tangent.dot(generatrix), -1.0, 1.0));
      EXPECT_NEAR(angle, 78.0 * kDegree, 1e-7) << s << " " << along;
    }
  // The offset angle is the first blade's angle where its segment starts.
  for (int s = 0; s < 3; ++s)
    EXPECT_NEAR(drum.blade_angle(s, drum.segment_start(s)),
                drum.parameters().offset_angles[static_cast<std::size_t>(s)], 1e-15);
}

TEST(TruckDrum, BladeDistanceAcrossInsideAndBeyondTheStrip) {
  const TruckDrumGeometry drum(eight_cubic_metre_drum());
  const double t = 0.008;
  for (int s = 0; s < 3; ++s) {
    const double z = drum.segment_start(s) + 0.7;
    const double r = drum.radius_at(z);
    for (const double turn : {0.0, std::numbers::pi}) {  // both blades of the segment
      const double theta = drum.blade_angle(s, z) + turn;
      // On the sheet, mid-height: half the thickness inside.
      EXPECT_NEAR(drum.blade_distance(at(z, theta, r - 0.1)), -0.5 * t, 1e-12) << s;
      // Beyond the inner edge, on the sheet: the radial gap.
      EXPECT_NEAR(drum.blade_distance(at(z, theta, r - 0.25 - 0.03)), 0.03, 1e-12) << s;
      // Across the sheet at the shell: the circumferential offset times the sheet's slope.
      const double rho = r - 0.05;
      const double twist = rho * drum.blade_twist(s, z);
      for (const double gap : {0.01, 0.05}) {
        const double offset = (gap + 0.5 * t) * std::sqrt(1.0 + twist * twist) / rho;
        EXPECT_NEAR(drum.blade_distance(at(z, theta + offset, rho)), gap, 1e-12) << s;
        EXPECT_NEAR(drum.blade_distance(at(z, theta - offset, rho)), gap, 1e-12) << s;
      }
    }
  }
  // Across a cylinder blade, the distance along the sheet's normal: first order in the offset.
  const double z = 2.6;
  const double theta = drum.blade_angle(1, z);
  const double beta = 78.0 * kDegree;
  const Vec3 normal(-std::sin(theta) * std::cos(beta), std::cos(theta) * std::cos(beta),
                    -std::sin(beta));
  for (const double d : {0.01, 0.03}) {
    const Vec3 x = at(z, theta, 1.15) + (d + 0.5 * t) * normal;
    EXPECT_NEAR(drum.blade_distance(x), d, 2e-3 * (d + 0.5 * t)) << d;
  }
  // The cavity less the blades: the shell's distance away from them, the blade's inside one.
  EXPECT_NEAR(drum.signed_distance(at(2.6, theta + 1.0, 1.12)), -0.03, 1e-12);
  EXPECT_NEAR(drum.signed_distance(at(z, theta, 1.05)), 0.5 * t, 1e-12);
}

TEST(TruckDrum, BadParametersAreNamed) {
  TruckDrumParameters p = eight_cubic_metre_drum();
  p.opening_radius = 1.3;
  EXPECT_THROW(TruckDrumGeometry{p}, std::invalid_argument);
  p = eight_cubic_metre_drum();
  p.helix_angle = 90.0 * kDegree;
  EXPECT_THROW(TruckDrumGeometry{p}, std::invalid_argument);
  p = eight_cubic_metre_drum();
  p.blade_height = 0.4;
  try {
    TruckDrumGeometry{p};
    ADD_FAILURE() << "a blade higher than the opening's radius";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("blade_height"), std::string::npos);
  }
}

}  // namespace
}  // namespace partimix::geometry
