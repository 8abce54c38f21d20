// The glyph tensors of a turned grain (docs/dem.md, "Drawing superquadric grains in ParaView"):
// - shape_tensor: symmetric, its eigenvalues the half-axes (a, b, c) and its eigenvectors the
//   body axes in the world frame (to 1e-12, relative to c), and it maps the unit sphere onto the
//   grain's ellipsoid (as the Tensor Glyph filter does, eigenvalues extracted or not);
// - superquadric_glyph_axes: ParaView's superquadric source (VTK's vtkSuperquadricSource: symmetry
//   axis y, size 1, theta roundness 2/n2, phi roundness 2/n1), each point sent through the
//   tensor's columns as the filter does with eigenvalues not extracted, lies on the grain's
//   surface F = 0 (to 1e-12), for a blocky grain; its determinant is a b c (no reflection).
#include "dem/glyph_tensors.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <cmath>
#include <numbers>

#include "dem/superquadric.hpp"

namespace partimix::dem {
namespace {

constexpr double kPi = std::numbers::pi;
const Vec3 kHalfAxes(1.0e-3, 2.0e-3, 3.5e-3);

Quaternion turned() {
  return Quaternion(Eigen::AngleAxisd(0.7, Vec3(1.0, 2.0, 3.0).normalized())) *
         Quaternion(Eigen::AngleAxisd(1.1, Vec3::UnitX()));
}

TEST(GlyphTensors, ShapeTensorHasTheHalfAxesAsEigenvaluesAndTheBodyAxesAsEigenvectors) {
  const Quaternion q = turned();
  const Mat3 rotation = q.toRotationMatrix();
  const Mat3 tensor = shape_tensor(q, kHalfAxes);
  const double tolerance = 1e-12 * kHalfAxes.maxCoeff();
  EXPECT_LE((tensor - tensor.transpose()).cwiseAbs().maxCoeff(), tolerance);
  const Eigen::SelfAdjointEigenSolver<Mat3> solver(tensor);
  for (int k = 0; k < 3; ++k) {  // eigenvalues ascending, as the half-axes here
    EXPECT_NEAR(solver.eigenvalues()(k), kHalfAxes(k), tolerance) << k;
    EXPECT_NEAR(std::abs(solver.eigenvectors().col(k).dot(rotation.col(k))), 1.0, 1e-12) << k;
    EXPECT_LE((tensor * rotation.col(k) - kHalfAxes(k) * rotation.col(k)).norm(), tolerance) << k;
  }
}

TEST(GlyphTensors, ShapeTensorMapsTheUnitSphereOntoTheEllipsoid) {
  const Quaternion q = turned();
  const Mat3 tensor = shape_tensor(q, kHalfAxes);
  const Superquadric ellipsoid(kHalfAxes, 2.0, 2.0);
  for (double theta = 0.05; theta < kPi; theta += 0.3) {
    for (double phi = 0.0; phi < 2.0 * kPi; phi += 0.4) {
      const Vec3 p(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                   std::cos(theta));
      const Vec3 body = q.conjugate() * (tensor * p);
      EXPECT_NEAR(ellipsoid.value(body), 0.0, 1e-12) << theta << " " << phi;
    }
  }
}

// VTK's signed powers of the superquadric source: sgn(c) |c|^m for c = cos w, sin w.
double cos_power(double w, double m) {
  const double c = std::cos(w);
  return std::copysign(std::pow(std::abs(c), m), c);
}
double sin_power(double w, double m) {
  const double s = std::sin(w);
  return std::copysign(std::pow(std::abs(s), m), s);
}

TEST(GlyphTensors, SuperquadricAxesSendParaViewsSourceOntoTheGrain) {
  const double n1 = 4.0;
  const double n2 = 6.0;
  const Superquadric grain(kHalfAxes, n1, n2);
  const Quaternion q = turned();
  const Mat3 axes = superquadric_glyph_axes(q, kHalfAxes);
  EXPECT_NEAR(axes.determinant(), kHalfAxes.prod(), 1e-12 * kHalfAxes.prod());
  const double theta_roundness = 2.0 / n2;
  const double phi_roundness = 2.0 / n1;
  for (double phi = -0.5 * kPi + 0.05; phi < 0.5 * kPi; phi += 0.2) {
    for (double theta = -kPi; theta < kPi; theta += 0.25) {
      // The source of size 1 with its symmetry axis y (vtkSuperquadricSource, AxisOfSymmetry 1).
      const double ring = cos_power(phi, phi_roundness);
      const Vec3 source(ring * sin_power(theta, theta_roundness), sin_power(phi, phi_roundness),
                        ring * cos_power(theta, theta_roundness));
      const Vec3 body = q.conjugate() * (axes * source);
      EXPECT_NEAR(grain.value(body), 0.0, 1e-12) << theta << " " << phi;
    }
  }
}

}  // namespace
}  // namespace partimix::dem
