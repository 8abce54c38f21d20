#include "dem/surface_curvature.hpp"

#include <algorithm>
#include <cmath>

namespace partimix::dem {
namespace {

// The adjugate (transposed cofactor matrix) of a symmetric 3 x 3 matrix, which needs no inverse:
// the Hessian is singular on the flat faces of blocky grains.
Mat3 adjugate(const Mat3& h) {
  Mat3 adj;
  adj(0, 0) = h(1, 1) * h(2, 2) - h(1, 2) * h(2, 1);
  adj(1, 1) = h(0, 0) * h(2, 2) - h(0, 2) * h(2, 0);
  adj(2, 2) = h(0, 0) * h(1, 1) - h(0, 1) * h(1, 0);
  adj(0, 1) = adj(1, 0) = h(0, 2) * h(2, 1) - h(0, 1) * h(2, 2);
  adj(0, 2) = adj(2, 0) = h(0, 1) * h(1, 2) - h(0, 2) * h(1, 1);
  adj(1, 2) = adj(2, 1) = h(0, 2) * h(1, 0) - h(0, 0) * h(1, 2);
  return adj;
}

}  // namespace

double mean_curvature(const Vec3& gradient, const Mat3& hessian) {
  const double g2 = gradient.squaredNorm();
  return (g2 * hessian.trace() - gradient.dot(hessian * gradient)) / (2.0 * g2 * std::sqrt(g2));
}

double gaussian_curvature(const Vec3& gradient, const Mat3& hessian) {
  const double g2 = gradient.squaredNorm();
  return gradient.dot(adjugate(hessian) * gradient) / (g2 * g2);
}

double hertz_radius(const Superquadric& shape, const Vec3& body_point, HertzRadius kind,
                    double limit) {
  const double r = shape.equivalent_radius();
  if (kind == HertzRadius::equivalent)
    return r;
  const Vec3 gradient = shape.gradient(body_point);
  if (!(gradient.squaredNorm() > 0.0))  // the centre: no surface through it
    return r;
  const Mat3 hessian = shape.hessian(body_point);
  const double curvature = kind == HertzRadius::mean_curvature
                               ? mean_curvature(gradient, hessian)
                               : std::sqrt(std::max(gaussian_curvature(gradient, hessian), 0.0));
  // 1 / curvature within [r / limit, limit r]; a vanishing curvature gives limit r.
  return std::clamp(1.0 / std::max(curvature, 1.0 / (limit * r)), r / limit, limit * r);
}

}  // namespace partimix::dem
