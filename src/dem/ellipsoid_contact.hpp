#pragma once
// Contact detection between two ellipsoids, spheres included (docs/dem.md, "Ellipsoid pairs: the
// midway point in one unknown"): the Perram-Wertheim contact function F(t) maximised over t in
// [0, 1] by a bracketed Newton iteration with 3 x 3 solves. The result is the midway point of
// find_contact (dem/superquadric_contact.hpp), with the same normal, overlap and contact point,
// without its powers and 4 x 4 systems. A pure function of its inputs that does not allocate.
#include <optional>

#include "core/vec.hpp"
#include "dem/superquadric_contact.hpp"

namespace partimix::dem {

// An ellipsoid in the world frame: (x - centre)^T A (x - centre) <= 1 with
// A = R diag(a^-2, b^-2, c^-2) R^T, R its rotation (body to world).
struct Ellipsoid {
  Vec3 centre;
  Mat3 rotation;
  Vec3 half_axes;
  Mat3 inverse_shape;  // A^-1 = R diag(a^2, b^2, c^2) R^T (ellipsoid_inverse_shape)

  // (x^T A x) for a world vector x from the centre.
  double quadratic_form(const Vec3& x) const;
};

Mat3 ellipsoid_inverse_shape(const Mat3& rotation, const Vec3& half_axes);

// The separating-axis test on the centre line d (from i to j): true when the grains' extents
// along u = d / |d|, sqrt(u^T A^-1 u) each (an ellipsoid's support distance), add up to less
// than |d|, so that they cannot touch (docs/dem.md, "Ellipsoid pairs"). Two quadratic forms, no
// 3 x 3 solve: the cheap rejection of the pairs whose bounding spheres overlap.
bool apart_along_centre_line(const Mat3& inverse_shape_i, const Vec3& d,
                             const Mat3& inverse_shape_j);
// |d| - sqrt(u^T A_i^-1 u) - sqrt(u^T A_j^-1 u): the gap between the grains' extents along the
// centre line, a lower bound on their distance when positive.
double centre_line_gap(const Mat3& inverse_shape_i, const Vec3& d, const Mat3& inverse_shape_j);
Ellipsoid make_ellipsoid(const Vec3& centre, const Mat3& rotation, const Vec3& half_axes);

// The contact of ellipsoid i with ellipsoid j, the iteration started from the multiplier mu of
// the last step's midway point when given (t = 1 / (1 + mu^2)), else from the equivalent spheres
// on the centre line. `near` is false (and nothing else set) when the bounding spheres are apart
// or the grains' extents along the centre line do not meet (a separating axis), with `gap` that
// of the bounding spheres or the centre line; the midway point, normal, overlap and contact point
// are set for touching grains only (mu, the warm start, always).
SuperquadricContact find_ellipsoid_contact(const Ellipsoid& i, const Ellipsoid& j,
                                           std::optional<double> mu);
// The same for a pair known to pass both tests (the DEM solver makes them first): Newton alone.
// `gap` of an apart pair is (sqrt(F) - 1)(a_i + a_j), F > 1 the contact function where the
// iteration stopped and a the smallest half-axes (docs/dem.md, "Pairs known apart").
SuperquadricContact solve_ellipsoid_contact(const Ellipsoid& i, const Ellipsoid& j,
                                            std::optional<double> mu);

}  // namespace partimix::dem
