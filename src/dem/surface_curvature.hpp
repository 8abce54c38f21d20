#pragma once
// The radius of a superquadric's surface at a point for the Hertz law (docs/dem.md, "Hertz
// radius"): from the mean or Gaussian curvature of the implicit surface F = 0 (Goldman 2005,
// Comput. Aided Geom. Des. 22, 632, section 4), clamped about the volume-equivalent radius.
#include "core/vec.hpp"
#include "dem/superquadric.hpp"

namespace partimix::dem {

enum class HertzRadius { equivalent, mean_curvature, gaussian_curvature };

// kappa_M = (|g|^2 tr H - g^T H g) / (2 |g|^3): 1/r on a sphere with its outward gradient.
double mean_curvature(const Vec3& gradient, const Mat3& hessian);
// K = g^T adj(H) g / |g|^4: 1/r^2 on a sphere.
double gaussian_curvature(const Vec3& gradient, const Mat3& hessian);

// The Hertz radius of `shape` at `body_point` (on or near its surface, body frame): 1/kappa_M or
// 1/sqrt(K), within [r / limit, limit r] with r the equivalent radius; r itself for
// HertzRadius::equivalent.
double hertz_radius(const Superquadric& shape, const Vec3& body_point, HertzRadius kind,
                    double limit);

}  // namespace partimix::dem
