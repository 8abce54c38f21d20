#include "dem/ellipsoid_contact.hpp"

#include <algorithm>
#include <cmath>

namespace partimix::dem {
namespace {

constexpr int kMaxIterations = 60;
// The last step: a Newton step s whose own error |F''' / (2 F'')| s^2 is below this (on t,
// which lies in (0, 1)), taken to second order so that its error is of order s^3 (docs/dem.md).
constexpr double kLastStepError = 1e-10;

// F(t) and its first three derivatives, with y = C(t)^-1 d, dy/dt = -C^-1 D y = -z and
// d2y/dt2 = 2 C^-1 D z (docs/dem.md, "Ellipsoid pairs"); F only when F > 1, which proves the
// grains apart.
struct ContactFunction {
  double value;
  double slope;
  double curvature;
  double third;
  Vec3 y;
  Vec3 dy_dt;
  Vec3 d2y_dt2;
};

// The pair's data for the contact function: d and the two inverse shapes, B_i and B_j - B_i.
struct Pencil {
  Vec3 d;
  const SymMat3& inverse_shape_i;
  SymMat3 difference;
};

ContactFunction contact_function(const Pencil& p, double t) {
  const SymMat3 c_inverse = p.inverse_shape_i.plus_scaled(t, p.difference).inverse();
  const double u = t * (1.0 - t);
  ContactFunction f{0.0, 0.0, 0.0, 0.0, c_inverse * p.d, Vec3::Zero(), Vec3::Zero()};
  const double s = p.d.dot(f.y);
  f.value = u * s;
  if (f.value > 1.0)
    return f;
  const Vec3 dy = p.difference * f.y;
  const Vec3 z = c_inverse * dy;
  const Vec3 dz = p.difference * z;
  f.dy_dt = -z;
  f.d2y_dt2 = 2.0 * (c_inverse * dz);
  const double q = f.y.dot(dy);
  const double w = dy.dot(z);
  const double r = z.dot(dz);
  f.slope = (1.0 - 2.0 * t) * s - u * q;
  f.curvature = -2.0 * s - 2.0 * (1.0 - 2.0 * t) * q + 2.0 * u * w;
  f.third = 6.0 * (q + (1.0 - 2.0 * t) * w - u * r);
  return f;
}

// The cold start: the equivalent spheres along the centre line, t0 = r_i / (r_i + r_j) with
// r = |d| / N(d) each grain's radius towards the other.
double centre_line_start(const EllipsoidView& i, const EllipsoidView& j, const Vec3& d) {
  const double inverse_radius_i = std::sqrt(i.form.shape.quadratic(d));
  const double inverse_radius_j = std::sqrt(j.form.shape.quadratic(d));
  return inverse_radius_j / (inverse_radius_i + inverse_radius_j);
}

struct Maximum {
  double t;
  ContactFunction f;
  int iterations;
  bool converged;
};

// Newton's method on F'(t) = 0 inside the bracket [lo, hi] that F' > 0 below the root and
// F' < 0 above it narrow; a step leaving the bracket is replaced by bisection. F(t) <= F* for
// every t, so F > 1 at any iterate proves the grains apart: the search stops there. A Newton
// step s = -F'/F'' whose error kappa s^2 (kappa = F'''/(2 F'')) is below kLastStepError is the
// last: taken to second order, delta = s - kappa s^2, with y and F to second order in delta.
// Without convergence, t and F are those of the last iterate (one call of contact_function,
// which the compiler inlines).
Maximum maximise(const Pencil& p, double t) {
  double lo = 0.0;
  double hi = 1.0;
  for (int n = 1;; ++n) {
    ContactFunction f = contact_function(p, t);
    if (f.value > 1.0)
      return {t, f, n, true};
    const double step = f.curvature < 0.0 ? -f.slope / f.curvature : 0.0;
    const double kappa = f.curvature < 0.0 ? f.third / (2.0 * f.curvature) : 0.0;
    const double delta = step - kappa * step * step;
    if (f.curvature < 0.0 && std::abs(kappa) * step * step <= kLastStepError && t + delta > lo &&
        t + delta < hi) {
      f.y += delta * f.dy_dt + 0.5 * delta * delta * f.d2y_dt2;
      f.value += delta * f.slope + 0.5 * delta * delta * f.curvature;
      return {t + delta, f, n, true};
    }
    if (n == kMaxIterations)
      return {t, f, n, false};
    (f.slope > 0.0 ? lo : hi) = t;
    t = t + step > lo && t + step < hi ? t + step : 0.5 * (lo + hi);
  }
}

// The surface points x* + alpha n of i and x* + beta n of j, from their quadratics in the forms
// without cancellation (docs/dem.md).
void add_surface_points(const EllipsoidView& i, const EllipsoidView& j, const Maximum& m,
                        SuperquadricContact& c) {
  const double depth = 1.0 - m.f.value;
  const double y = c.normal.dot(m.f.y);  // |y|: the normal is y / |y|
  const double b_i = (1.0 - m.t) * y;
  const double b_j = m.t * y;
  const double alpha =
      depth / (b_i + std::sqrt(b_i * b_i + i.form.shape.quadratic(c.normal) * depth));
  const double beta =
      -depth / (b_j + std::sqrt(b_j * b_j + j.form.shape.quadratic(c.normal) * depth));
  c.overlap = alpha - beta;
  c.point = c.midway + 0.5 * (alpha + beta) * c.normal;
}

}  // namespace

// With q = d^T A^-1 d, |d|^2 > sqrt(q_i) + sqrt(q_j) squared twice: no square root.
bool apart_along_centre_line(const SymMat3& inverse_shape_i, const Vec3& d,
                             const SymMat3& inverse_shape_j) {
  const double q_i = inverse_shape_i.quadratic(d);
  const double q_j = inverse_shape_j.quadratic(d);
  const double d2 = d.squaredNorm();
  const double excess = d2 * d2 - q_i - q_j;
  return excess > 0.0 && excess * excess > 4.0 * q_i * q_j;
}

double centre_line_gap(const SymMat3& inverse_shape_i, const Vec3& d,
                       const SymMat3& inverse_shape_j) {
  const double distance = d.norm();
  return distance -
         (std::sqrt(inverse_shape_i.quadratic(d)) + std::sqrt(inverse_shape_j.quadratic(d))) /
             distance;
}

EllipsoidForm ellipsoid_form(const Mat3& rotation, const Vec3& half_axes) {
  const Vec3 squares = half_axes.cwiseAbs2();
  return {SymMat3::rotated_diagonal(rotation, squares),
          SymMat3::rotated_diagonal(rotation, squares.cwiseInverse())};
}

Ellipsoid make_ellipsoid(const Vec3& centre, const Mat3& rotation, const Vec3& half_axes) {
  return {centre, ellipsoid_form(rotation, half_axes), half_axes};
}

SuperquadricContact find_ellipsoid_contact(const Ellipsoid& i, const Ellipsoid& j,
                                           std::optional<double> mu) {
  const Vec3 d = j.centre - i.centre;
  const double reach = i.half_axes.maxCoeff() + j.half_axes.maxCoeff();
  if (d.squaredNorm() >= reach * reach) {
    SuperquadricContact c;
    c.gap = d.norm() - reach;
    return c;
  }
  if (apart_along_centre_line(i.form.inverse_shape, d, j.form.inverse_shape)) {
    SuperquadricContact c;
    c.gap = centre_line_gap(i.form.inverse_shape, d, j.form.inverse_shape);
    return c;
  }
  return solve_ellipsoid_contact({i.centre, i.form, i.half_axes.minCoeff()},
                                 {j.centre, j.form, j.half_axes.minCoeff()}, mu);
}

SuperquadricContact solve_ellipsoid_contact(const EllipsoidView& i, const EllipsoidView& j,
                                            std::optional<double> mu) {
  const Vec3 d = j.centre - i.centre;
  SuperquadricContact c;
  c.near = true;
  if (d.squaredNorm() == 0.0) {
    c.converged = false;
    return c;
  }
  const double start = mu ? 1.0 / (1.0 + *mu * *mu) : centre_line_start(i, j, d);
  const Pencil pencil{d, i.form.inverse_shape, j.form.inverse_shape - i.form.inverse_shape};
  const Maximum m = maximise(pencil, std::clamp(start, 1e-6, 1.0 - 1e-6));
  c.converged = m.converged;
  c.iterations = m.iterations;
  c.mu = std::sqrt((1.0 - m.t) / m.t);
  c.touching = m.converged && m.f.value < 1.0;
  if (m.converged && !c.touching)  // sqrt(F) E_i contains E_i grown by (sqrt(F) - 1) a_i
    c.gap = (std::sqrt(m.f.value) - 1.0) * (i.smallest_half_axis + j.smallest_half_axis);
  if (c.touching) {
    c.midway = i.centre + (1.0 - m.t) * (i.form.inverse_shape * m.f.y);
    c.normal = m.f.y.normalized();
    add_surface_points(i, j, m, c);
  }
  return c;
}

}  // namespace partimix::dem
