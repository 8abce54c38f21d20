#pragma once
// Contact detection between two ellipsoids, spheres included (docs/dem.md, "Ellipsoid pairs: the
// midway point in one unknown"): the Perram-Wertheim contact function F(t) maximised over t in
// [0, 1] by a bracketed Newton iteration with 3 x 3 solves. The result is the midway point of
// find_contact (dem/superquadric_contact.hpp), with the same normal, overlap and contact point,
// without its powers and 4 x 4 systems. A pure function of its inputs that does not allocate.
#include <optional>

#include "core/symmetric_matrix.hpp"
#include "core/vec.hpp"
#include "dem/superquadric_contact.hpp"

namespace partimix::dem {

// An ellipsoid's matrices in the world frame, for its present orientation:
// (x - centre)^T A (x - centre) <= 1 with A = R diag(a^-2, b^-2, c^-2) R^T, R its rotation (body
// to world). Six entries each (core/symmetric_matrix.hpp): 96 bytes, two cache lines.
struct alignas(32) EllipsoidForm {
  SymMat3 inverse_shape;  // A^-1 = R diag(a^2, b^2, c^2) R^T
  SymMat3 shape;          // A
};

EllipsoidForm ellipsoid_form(const Mat3& rotation, const Vec3& half_axes);

// An ellipsoid, for the tests and the general contact code.
struct Ellipsoid {
  Vec3 centre;
  EllipsoidForm form;
  Vec3 half_axes;
};

Ellipsoid make_ellipsoid(const Vec3& centre, const Mat3& rotation, const Vec3& half_axes);

// One grain of a pair as the DEM solver holds it, without copies: its centre (the image nearest
// to the other grain), its form, and its smallest half-axis (for the gap of an apart pair).
struct EllipsoidView {
  const Vec3& centre;
  const EllipsoidForm& form;
  double smallest_half_axis;
};

// The separating-axis test on the centre line d (from i to j): true when the grains' extents
// along u = d / |d|, sqrt(u^T A^-1 u) each (an ellipsoid's support distance), add up to less
// than |d|, so that they cannot touch (docs/dem.md, "Ellipsoid pairs"). Two quadratic forms, no
// 3 x 3 solve: the cheap rejection of the pairs whose bounding spheres overlap.
bool apart_along_centre_line(const SymMat3& inverse_shape_i, const Vec3& d,
                             const SymMat3& inverse_shape_j);
// |d| - sqrt(u^T A_i^-1 u) - sqrt(u^T A_j^-1 u): the gap between the grains' extents along the
// centre line, a lower bound on their distance when positive.
double centre_line_gap(const SymMat3& inverse_shape_i, const Vec3& d,
                       const SymMat3& inverse_shape_j);

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
SuperquadricContact solve_ellipsoid_contact(const EllipsoidView& i, const EllipsoidView& j,
                                            std::optional<double> mu);

}  // namespace partimix::dem
