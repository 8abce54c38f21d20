#pragma once
// A brute-force reference for the contact of two superquadric grains, independent of
// dem/superquadric_contact.cpp and dem/superquadric_gauge.cpp (used by
// tests/dem/superquadric_contact_test.cpp). It rests on each grain's support function
// h(n) = max over the grain of (x - centre) . n, in closed form: the gauge
// ((|x/a|^n2 + |y/b|^n2)^(n1/n2) + |z/c|^n1)^(1/n1) is a nested norm, so h is the nested dual
// norm ((|a m_x|^q2 + |b m_y|^q2)^(q1/q2) + |c m_z|^q1)^(1/q1) of m = Q^T n, 1/q + 1/n = 1.
// With the Minkowski difference M of the grains (h_M(n) = h_i(n) + h_j(-n)) and d = c_j - c_i:
// - the grains, each scaled by lambda about its centre, first touch at
//   lambda* = max_n n . d / h_M(n) (the gauge of M at d), with the normal n* that maximises and
//   the touching point c_i + lambda* s_i(n*) (s: the support point). That is the midway point
//   of the gauges (docs/dem.md), found here by a search over all directions;
// - the penetration depth, the shortest translation that separates the grains, is
//   min_n h_M(n) - n . d (negative: separated), again by a search over all directions.
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "dem/superquadric.hpp"
#include "dem/superquadric_contact.hpp"

namespace partimix::dem::reference {

// h(n) for a unit n.
inline double support_value(const GrainPose& g, const Vec3& n) {
  const Superquadric& shape = *g.shape;
  const double q1 = shape.n1() / (shape.n1() - 1.0);
  const double q2 = shape.n2() / (shape.n2() - 1.0);
  const Vec3 scaled = shape.half_axes().cwiseProduct(g.rotation.transpose() * n).cwiseAbs();
  const double in_plane = std::pow(std::pow(scaled.x(), q2) + std::pow(scaled.y(), q2), 1.0 / q2);
  return std::pow(std::pow(in_plane, q1) + std::pow(scaled.z(), q1), 1.0 / q1);
}

// The support point s(n) = grad h(n), relative to the centre, world frame:
// dh/dr = (r / h)^(q1 - 1) and dr/dA = (A / r)^(q2 - 1) with r the in-plane norm, A = |a m_x|.
inline Vec3 support_point(const GrainPose& g, const Vec3& n) {
  const Superquadric& shape = *g.shape;
  const double q1 = shape.n1() / (shape.n1() - 1.0);
  const double q2 = shape.n2() / (shape.n2() - 1.0);
  const Vec3 m = g.rotation.transpose() * n;
  const Vec3 scaled = shape.half_axes().cwiseProduct(m).cwiseAbs();
  const double in_plane = std::pow(std::pow(scaled.x(), q2) + std::pow(scaled.y(), q2), 1.0 / q2);
  const double h = std::pow(std::pow(in_plane, q1) + std::pow(scaled.z(), q1), 1.0 / q1);
  Vec3 point = Vec3::Zero();
  for (int k = 0; k < 2; ++k) {
    if (in_plane > 0.0)
      point[k] = std::pow(in_plane / h, q1 - 1.0) * std::pow(scaled[k] / in_plane, q2 - 1.0);
  }
  point.z() = std::pow(scaled.z() / h, q1 - 1.0);
  for (int k = 0; k < 3; ++k)
    point[k] *= shape.half_axes()[k] * (m[k] < 0.0 ? -1.0 : 1.0);
  return g.rotation * point;
}

// Direction k of `count` spread evenly over the unit sphere (a Fibonacci lattice).
inline Vec3 fibonacci_direction(int k, int count) {
  const double z = 1.0 - (2.0 * k + 1.0) / count;
  const double phi = k * std::numbers::pi * (3.0 - std::sqrt(5.0));
  const double r = std::sqrt(1.0 - z * z);
  return {r * std::cos(phi), r * std::sin(phi), z};
}

// Pattern search to a local maximum of score over the unit sphere from n, down to steps of
// 1e-10: steps of a given angle in 8 tangent directions (4 lines) and along the great circles
// perpendicular to the grains' body axes, halved when none improves. h is only C1 across those
// circles (|t|^q, q near 1 for blocky grains): the maxima sit on ridges along them, which the
// 8 directions alone follow by ever smaller steps.
template <class Score>
Vec3 climb(const Score& score, const Mat3& axes_i, const Mat3& axes_j, Vec3 n, double step) {
  double best = score(n);
  while (step > 1e-10) {
    std::array<Vec3, 10> directions;
    const Vec3 e1 = n.unitOrthogonal();
    const Vec3 e2 = n.cross(e1);
    directions[0] = e1;
    directions[1] = e2;
    directions[2] = std::sqrt(0.5) * (e1 + e2);
    directions[3] = std::sqrt(0.5) * (e1 - e2);
    for (int k = 0; k < 3; ++k) {
      directions[4 + k] = axes_i.col(k).cross(n).normalized();
      directions[7 + k] = axes_j.col(k).cross(n).normalized();
    }
    bool moved = false;
    for (const Vec3& e : directions) {
      for (const double sign : {1.0, -1.0}) {
        const Vec3 trial = (n + sign * step * e).normalized();
        const double value = score(trial);
        if (value > best) {
          best = value;
          n = trial;
          moved = true;
          break;
        }
      }
      if (moved)
        break;
    }
    step = moved ? 2.0 * step : 0.5 * step;
  }
  return n;
}

constexpr int kDirections = 400;
constexpr double kFirstStep = 0.1;  // the lattice spacing is about sqrt(4 pi / 400) = 0.18

// The best `count` lattice directions for score, each climbed; the best result.
template <class Score>
Vec3 global_maximum(const Score& score, const GrainPose& i, const GrainPose& j, int count) {
  std::array<std::pair<double, int>, kDirections> ranked;
  for (int k = 0; k < kDirections; ++k)
    ranked[k] = {score(fibonacci_direction(k, kDirections)), k};
  std::partial_sort(ranked.begin(), ranked.begin() + count, ranked.end(),
                    [](const auto& a, const auto& b) { return a.first > b.first; });
  Vec3 best = fibonacci_direction(ranked[0].second, kDirections);
  double best_score = -1e300;
  for (int c = 0; c < count; ++c) {
    const Vec3 n = climb(score, i.rotation, j.rotation,
                         fibonacci_direction(ranked[c].second, kDirections), kFirstStep);
    if (score(n) > best_score) {
      best_score = score(n);
      best = n;
    }
  }
  return best;
}

// The gauges' midway point: lambda* = 1 + t* (t* < 0: touching), normal n* and point X*.
struct Midway {
  double scale;
  Vec3 normal;
  Vec3 point;
};

// n* maximises n . d / h_M(n), whose super-level sets on the sphere are convex (h_M is convex
// and homogeneous): one climb from the best lattice direction finds it. It does not depend on
// |d|.
inline Vec3 midway_normal(const GrainPose& i, const GrainPose& j) {
  const Vec3 d = j.centre - i.centre;
  const auto ratio = [&](const Vec3& n) {
    return n.dot(d) / (support_value(i, n) + support_value(j, -n));
  };
  return global_maximum(ratio, i, j, 1);
}

inline Midway midway(const GrainPose& i, const GrainPose& j, const Vec3& normal) {
  const double scale =
      normal.dot(j.centre - i.centre) / (support_value(i, normal) + support_value(j, -normal));
  return {scale, normal, i.centre + scale * support_point(i, normal)};
}

// Minus the penetration depth: its minimum may have several local minima on the sphere (a box's
// faces), so the best 4 lattice directions are climbed.
struct Penetration {
  double depth;
  Vec3 normal;  // out of i towards j
  Vec3 point;   // halfway between the deepest points of each grain along the normal
};

inline Penetration penetration(const GrainPose& i, const GrainPose& j) {
  const Vec3 d = j.centre - i.centre;
  const auto minus_depth = [&](const Vec3& n) {
    return n.dot(d) - support_value(i, n) - support_value(j, -n);
  };
  const Vec3 n = global_maximum(minus_depth, i, j, 4);
  const Vec3 deepest_i = i.centre + support_point(i, n);
  const Vec3 deepest_j = j.centre + support_point(j, -n);
  return {-minus_depth(n), n, 0.5 * (deepest_i + deepest_j)};
}

// The distance from x (inside the grain) along the unit e to its surface: bisection on
// F = Superquadric::value.
inline double surface_distance(const GrainPose& g, const Vec3& x, const Vec3& e) {
  const auto outside = [&](double s) {
    return g.shape->value(g.rotation.transpose() * (x + s * e - g.centre)) > 0.0;
  };
  double inside = 0.0;
  double out = 2.0 * g.shape->bounding_radius() + (x - g.centre).norm();
  for (int k = 0; k < 200 && out - inside > 1e-15 * out; ++k) {
    const double s = 0.5 * (inside + out);
    (outside(s) ? out : inside) = s;
  }
  return 0.5 * (inside + out);
}

}  // namespace partimix::dem::reference
