// The truck drum as a wall (docs/truck-drum.md, "As a wall"): placed by its head's centre and a
// tilted axis, its frame is a rotation (distances kept to 1e-12 m) that takes the axis to z; its
// contact surface (the shell open at the opening and the blades, one two-sided mesh) agrees with
// the analytic signed distance near the shell within the chords' sagitta plus 0.5 mm (0.6 mm +
// 0.5 mm at 96 divisions) and near a blade's face within 1 mm (its distance is first order in
// the offset across the sheet), and a grain past the opening touches nothing.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>

#include "eight_cubic_metre_drum.hpp"
#include "geometry/truck_drum_shape.hpp"

namespace partimix::geometry {
namespace {

constexpr double kTilt = 15.0 * std::numbers::pi / 180.0;

const Vec3 kHead(1.0, 2.0, 0.5);
const Vec3 kAxis(std::cos(kTilt), 0.0, std::sin(kTilt));

const TruckDrumShape& shape() {
  static const TruckDrumShape drum(eight_cubic_metre_drum(), kHead, 3.0 * kAxis, 96);
  return drum;
}

// A point of the case at (z, θ, ρ) of the drum's own frame.
Vec3 from_drum(double z, double theta, double rho) {
  return shape().from_drum(Vec3(rho * std::cos(theta), rho * std::sin(theta), z));
}

TEST(TruckDrumShape, ItsFrameIsARotationThatTakesTheAxisToZ) {
  const double length = shape().drum().length();
  const Vec3 local(0.3, -0.2, 1.1);
  EXPECT_LT((shape().to_drum(shape().from_drum(local)) - local).norm(), 1e-15);
  EXPECT_LT(shape().to_drum(kHead).norm(), 1e-12);
  EXPECT_LT((shape().to_drum(kHead + length * kAxis) - Vec3(0.0, 0.0, length)).norm(), 1e-12);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(-4.0, 4.0);
  for (int i = 0; i < 100; ++i) {
    const Vec3 a(coordinate(random), coordinate(random), coordinate(random));
    const Vec3 b(coordinate(random), coordinate(random), coordinate(random));
    EXPECT_NEAR((shape().to_drum(a) - shape().to_drum(b)).norm(), (a - b).norm(), 1e-12);
    EXPECT_EQ(shape().signed_distance(a), shape().drum().signed_distance(shape().to_drum(a)));
  }
}

TEST(TruckDrumShape, TheOpeningIsItsOpenEnd) {
  const double length = shape().drum().length();
  EXPECT_TRUE(shape().beyond_open_end(from_drum(length + 0.01, 0.0, 0.1), {}));
  EXPECT_FALSE(shape().beyond_open_end(from_drum(length - 0.01, 0.0, 0.1), {}));
  EXPECT_FALSE(shape().beyond_open_end(from_drum(-0.01, 0.0, 0.1), {}));
  EXPECT_GT(shape().signed_distance(from_drum(-0.01, 0.0, 0.1)), 0.0);
}

TEST(TruckDrumShape, TheSurfaceAgreesWithTheSignedDistanceNearTheShell) {
  const auto surface = shape().make_surface(false, {});
  const TruckDrumGeometry& drum = shape().drum();
  const double sagitta = drum.parameters().radius * (1.0 - std::cos(std::numbers::pi / 96));
  int checked = 0;
  for (double z = 0.3; z < drum.length() - 0.2; z += 0.1)
    for (double theta = 0.0; theta < 2.0 * std::numbers::pi; theta += 0.37) {
      const double rho = drum.radius_at(z) - 0.04;
      const Vec3 x = from_drum(z, theta, rho);
      const double shell = drum.shell_distance(shape().to_drum(x));
      if (drum.blade_distance(shape().to_drum(x)) < 0.1)
        continue;  // a blade is nearer than the shell, or near enough to answer
      SurfacePoint point;
      ASSERT_TRUE(surface->nearest(x, 1.0, point)) << z << " " << theta;
      EXPECT_NEAR(point.gap, -shell, sagitta + 5e-4) << z << " " << theta;
      EXPECT_GT(point.normal.dot(x - point.point), 0.0);
      ++checked;
    }
  EXPECT_GT(checked, 200);
}

TEST(TruckDrumShape, TheSurfaceAgreesWithTheBladesDistanceBesideTheirFaces) {
  const auto surface = shape().make_surface(false, {});
  const TruckDrumGeometry& drum = shape().drum();
  for (int s = 0; s < 3; ++s)
    for (double fraction : {0.2, 0.5, 0.8}) {
      const double z =
          drum.segment_start(s) + fraction * (drum.segment_start(s + 1) - drum.segment_start(s));
      const double rho = drum.radius_at(z) - 0.1;
      for (double side : {-1.0, 1.0}) {
        const double theta = drum.blade_angle(s, z) + side * 0.12 / rho;
        const Vec3 x = from_drum(z, theta, rho);
        const double expected = drum.blade_distance(shape().to_drum(x));
        ASSERT_GT(expected, 0.005);
        SurfacePoint point;
        ASSERT_TRUE(surface->nearest(x, 1.0, point));
        EXPECT_NEAR(point.gap, expected, 1e-3) << s << " " << fraction << " " << side;
      }
    }
}

TEST(TruckDrumShape, AGrainPastTheOpeningTouchesNothing) {
  const auto surface = shape().make_surface(false, {});
  const double length = shape().drum().length();
  SurfacePoint point;
  EXPECT_FALSE(surface->nearest(from_drum(length + 0.2, 0.0, 0.0), 0.1, point));
}

TEST(TruckDrumShape, AZeroAxisIsRejected) {
  EXPECT_THROW(TruckDrumShape(eight_cubic_metre_drum(), kHead, Vec3::Zero(), 96),
               std::invalid_argument);
}

}  // namespace
}  // namespace partimix::geometry
