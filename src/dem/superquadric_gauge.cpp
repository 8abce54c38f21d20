#include "dem/superquadric_gauge.hpp"

#include <cmath>

namespace partimix::dem {
namespace {

// u^n for u >= 0: by repeated squaring when n is a whole number up to 16 (every blockiness in
// the cases), std::pow otherwise.
double power(double u, double n) {
  if (n > 16.0 || n != std::floor(n))
    return std::pow(u, n);
  double result = 1.0;
  double base = u;
  for (int e = static_cast<int>(n); e > 0; e >>= 1) {
    if (e & 1)
      result *= base;
    base *= base;
  }
  return result;
}

double root(double s, double n) {
  return n == 2.0 ? std::sqrt(s) : std::pow(s, 1.0 / n);
}

// The powers of the scaled coordinates: U = |x/a|^n2, V = |y/b|^n2, W = |z/c|^n1,
// P = U + V, Q = P^(n1/n2) and S = Q + W = N^n1.
struct Powers {
  double u, v, w, p, q, s;
};

Powers powers(const Superquadric& shape, const Vec3& x) {
  const Vec3 scaled = x.cwiseQuotient(shape.half_axes()).cwiseAbs();
  Powers t{};
  t.u = power(scaled.x(), shape.n2());
  t.v = power(scaled.y(), shape.n2());
  t.w = power(scaled.z(), shape.n1());
  t.p = t.u + t.v;
  t.q = shape.n1() == shape.n2() ? t.p : power(t.p, shape.n1() / shape.n2());
  t.s = t.q + t.w;
  return t;
}

// For a power T = |x/a|^n: T / x and T / x^2 (the derivatives of T over n and n (n - 1)), with
// their limits on the plane x = 0 (n >= 2).
struct Slopes {
  double first;
  double second;
};

Slopes slopes(double power_value, double x, double a, double n) {
  if (x == 0.0)
    return {0.0, n == 2.0 ? 1.0 / (a * a) : 0.0};
  return {power_value / x, power_value / (x * x)};
}

}  // namespace

double gauge(const Superquadric& shape, const Vec3& x) {
  return root(powers(shape, x).s, shape.n1()) - 1.0;
}

// With k = N / S, grad N = k ((Q/P) U/x, (Q/P) V/y, W/z) and
// H_N = (N / (n1 S)) H_S - ((n1 - 1) / N) grad N grad N^T (docs/dem.md).
GaugeLocal gauge_local(const Superquadric& shape, const Vec3& x) {
  const double n1 = shape.n1();
  const double n2 = shape.n2();
  const Vec3& axes = shape.half_axes();
  const Powers t = powers(shape, x);
  const double norm = root(t.s, n1);
  GaugeLocal g;
  g.value = norm - 1.0;
  if (t.s <= 0.0)
    return g;
  const Slopes sx = slopes(t.u, x.x(), axes.x(), n2);
  const Slopes sy = slopes(t.v, x.y(), axes.y(), n2);
  const Slopes sz = slopes(t.w, x.z(), axes.z(), n1);
  const double k = norm / t.s;
  if (t.p > 0.0) {
    const double q_p = t.q / t.p;
    g.gradient = k * Vec3(q_p * sx.first, q_p * sy.first, sz.first);
    const double cross = k * (n1 - n2) * q_p / t.p;
    const double in_plane = k * (n2 - 1.0) * q_p;
    g.hessian(0, 0) = cross * sx.first * sx.first + in_plane * sx.second;
    g.hessian(1, 1) = cross * sy.first * sy.first + in_plane * sy.second;
    g.hessian(0, 1) = g.hessian(1, 0) = cross * sx.first * sy.first;
  } else {
    // On the z axis: the limits along the x and y axes, where S = |x/a|^n1 + W.
    g.gradient = k * Vec3(0.0, 0.0, sz.first);
    if (n1 == 2.0) {
      g.hessian(0, 0) = k / (axes.x() * axes.x());
      g.hessian(1, 1) = k / (axes.y() * axes.y());
    }
  }
  g.hessian(2, 2) = k * (n1 - 1.0) * sz.second;
  g.hessian -= (n1 - 1.0) / norm * g.gradient * g.gradient.transpose();
  return g;
}

}  // namespace partimix::dem
