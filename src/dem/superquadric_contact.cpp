#include "dem/superquadric_contact.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>

#include "dem/ellipsoid_contact.hpp"
#include "dem/oriented_box.hpp"
#include "dem/superquadric_gauge.hpp"

namespace partimix::dem {
namespace {

using Vec4 = Eigen::Vector4d;

// Levenberg-Marquardt's damping, relative to |J|^2.
constexpr double kSmallestDamping = 1e-12;
constexpr double kLargestDamping = 1e8;
constexpr double kLongestMove = 0.5;  // Newton's longest step in X, in units of L
constexpr double kLongestNu = 1.5;    // and in ln(mu^2)
constexpr int kSurfaceIterations = 50;
constexpr double kSurfaceTolerance = 1e-12;  // on the surface points' steps, in units of L

double length_scale(const GrainPose& i, const GrainPose& j) {
  return std::min(i.shape->half_axes().minCoeff(), j.shape->half_axes().minCoeff());
}

bool bounds_overlap(const GrainPose& i, const GrainPose& j) {
  const double reach = i.shape->bounding_radius() + j.shape->bounding_radius();
  if ((j.centre - i.centre).squaredNorm() >= reach * reach)
    return false;
  return boxes_overlap({i.centre, i.rotation, i.shape->half_axes()},
                       {j.centre, j.rotation, j.shape->half_axes()});
}

// A grain's G at a world point, its gradient and Hessian turned to the world frame.
GaugeLocal world_gauge(const GrainPose& g, const Vec3& x) {
  GaugeLocal local = gauge_local(*g.shape, g.rotation.transpose() * (x - g.centre));
  local.gradient = g.rotation * local.gradient;
  local.hessian = g.rotation * local.hessian * g.rotation.transpose();
  return local;
}

// Newton's unknowns X and nu = ln(mu^2) (mu^2 cannot change sign or reach 0, where |residual|
// has a spurious valley), both gauges at X and the residual, scaled by L (docs/dem.md).
struct Iterate {
  Vec3 x;
  double nu;
  GaugeLocal i;
  GaugeLocal j;
  Vec4 residual;
};

Vec4 residual(const GaugeLocal& i, const GaugeLocal& j, double nu, double length) {
  Vec4 r;
  r << length * (i.gradient + std::exp(nu) * j.gradient), i.value - j.value;
  return r;
}

Iterate evaluate(const GrainPose& i, const GrainPose& j, const Vec3& x, double nu, double length) {
  Iterate it{x, nu, world_gauge(i, x), world_gauge(j, x), Vec4::Zero()};
  it.residual = residual(it.i, it.j, nu, length);
  return it;
}

// The Jacobian of the scaled residual in (X / L, nu): [[H_i + mu^2 H_j, mu^2 grad G_j],
// [grad G_i^T - grad G_j^T, 0]] (docs/dem.md), scaled alike.
Eigen::Matrix4d jacobian(const Iterate& it, double length) {
  const double m = std::exp(it.nu);
  Eigen::Matrix4d jac;
  jac.topLeftCorner<3, 3>() = length * length * (it.i.hessian + m * it.j.hessian);
  jac.topRightCorner<3, 1>() = m * length * it.j.gradient;
  jac.bottomLeftCorner<1, 3>() = length * (it.i.gradient - it.j.gradient).transpose();
  jac(3, 3) = 0.0;
  return jac;
}

// The Levenberg-Marquardt step (J^T J + damping I) step = -J^T r, shortened to at most
// kLongestMove L in X and kLongestNu in nu: the gauges' gradients stay bounded far away, so
// |residual| alone would let the iteration wander off.
Vec4 damped_step(const Eigen::Matrix4d& jac, const Vec4& r, double damping) {
  const Eigen::Matrix4d normal = jac.transpose() * jac + damping * Eigen::Matrix4d::Identity();
  const Vec4 step = normal.ldlt().solve(-(jac.transpose() * r));
  const double longest =
      std::max(step.head<3>().norm() / kLongestMove, std::abs(step[3]) / kLongestNu);
  return longest > 1.0 ? Vec4(step / longest) : step;
}

struct Midway {
  Iterate it;
  bool converged;
  int iterations;
};

// Levenberg-Marquardt: a step that lowers |residual| is taken and the damping divided by 10;
// otherwise the damping grows tenfold (towards short gradient steps, which handle the nearly
// singular Jacobian of flat faces) until kLargestDamping.
Midway solve_midway(const GrainPose& i, const GrainPose& j, Iterate it, double length,
                    const ContactTolerance& tolerance) {
  double damping = kSmallestDamping;
  for (int n = 0; n < tolerance.max_iterations; ++n) {
    if (it.residual.lpNorm<Eigen::Infinity>() <= tolerance.residual)
      return {it, true, n};
    const Eigen::Matrix4d jac = jacobian(it, length);
    const double scale = jac.squaredNorm();
    const double norm = it.residual.norm();
    for (;;) {
      const Vec4 step = damped_step(jac, it.residual, damping * scale);
      Iterate trial = evaluate(i, j, it.x + length * step.head<3>(), it.nu + step[3], length);
      if (trial.residual.norm() < norm) {
        it = trial;
        damping = std::max(0.1 * damping, kSmallestDamping);
        break;
      }
      damping *= 10.0;
      if (damping > kLargestDamping)
        return {it, false, n + 1};
    }
  }
  return {it, it.residual.lpNorm<Eigen::Infinity>() <= tolerance.residual,
          tolerance.max_iterations};
}

// The cold start: on the segment between the centres, the point where G_i = G_j. The gauges
// grow linearly along it, so X = c_i + s d with s = N_j(-d) / (N_i(d) + N_j(-d)); mu^2 is the
// ratio of the gradients' lengths there (docs/dem.md).
Iterate centre_line_start(const GrainPose& i, const GrainPose& j, double length) {
  const Vec3 d = j.centre - i.centre;
  const double reach_i = gauge(*i.shape, i.rotation.transpose() * d) + 1.0;
  const double reach_j = gauge(*j.shape, -(j.rotation.transpose() * d)) + 1.0;
  Iterate it = evaluate(i, j, i.centre + reach_j / (reach_i + reach_j) * d, 0.0, length);
  it.nu = std::log(it.i.gradient.norm() / it.j.gradient.norm());
  it.residual = residual(it.i, it.j, it.nu, length);
  return it;
}

struct SurfaceDistance {
  double s;
  bool converged;
};

// The distance s from X (inside the grain) along the unit direction e to the grain's surface,
// G(X + s e) = 0. G is convex along the line, so Newton's iterates from s = 0 overshoot once and
// then fall monotonically to the root (docs/dem.md).
SurfaceDistance distance_to_surface(const GrainPose& g, const Vec3& x, const Vec3& e,
                                    double length) {
  const Vec3 body_x = g.rotation.transpose() * (x - g.centre);
  const Vec3 body_e = g.rotation.transpose() * e;
  double s = 0.0;
  for (int n = 0; n < kSurfaceIterations; ++n) {
    const GaugeLocal local = gauge_local(*g.shape, body_x + s * body_e);
    const double slope = local.gradient.dot(body_e);
    if (!(slope > 0.0))
      return {s, false};
    const double ds = local.value / slope;
    s -= ds;
    if (std::abs(ds) <= kSurfaceTolerance * length)
      return {s, true};
  }
  return {s, false};
}

SuperquadricContact contact_at(const GrainPose& i, const GrainPose& j, const Midway& m,
                               double length) {
  SuperquadricContact c;
  c.near = true;
  c.converged = m.converged;
  c.iterations = m.iterations;
  c.midway = m.it.x;
  c.mu = std::exp(0.5 * m.it.nu);
  c.normal = m.it.i.gradient.normalized();
  c.touching = m.converged && m.it.i.value < 0.0 && m.it.j.value < 0.0;
  if (!c.touching)
    return c;
  const SurfaceDistance along_i = distance_to_surface(i, c.midway, c.normal, length);
  const SurfaceDistance along_j = distance_to_surface(j, c.midway, -c.normal, length);
  c.converged = along_i.converged && along_j.converged;
  // alpha = s_i, beta = -s_j.
  c.overlap = along_i.s + along_j.s;
  c.point = c.midway + 0.5 * (along_i.s - along_j.s) * c.normal;
  return c;
}

}  // namespace

SuperquadricContact find_contact(const GrainPose& i, const GrainPose& j,
                                 const std::optional<MidwayStart>& start,
                                 const ContactTolerance& tolerance) {
  if (!i.shape->is_ellipsoid() || !j.shape->is_ellipsoid())
    return find_midway_contact(i, j, start, tolerance);
  return find_ellipsoid_contact(make_ellipsoid(i.centre, i.rotation, i.shape->half_axes()),
                                make_ellipsoid(j.centre, j.rotation, j.shape->half_axes()),
                                start ? std::optional<double>(start->mu) : std::nullopt);
}

SuperquadricContact find_midway_contact(const GrainPose& i, const GrainPose& j,
                                        const std::optional<MidwayStart>& start,
                                        const ContactTolerance& tolerance) {
  if (!bounds_overlap(i, j))
    return {};
  const double length = length_scale(i, j);
  int warm_iterations = 0;
  if (start) {
    const Midway warm = solve_midway(
        i, j, evaluate(i, j, start->midway, 2.0 * std::log(start->mu), length), length, tolerance);
    if (warm.converged)
      return contact_at(i, j, warm, length);
    warm_iterations = warm.iterations;
  }
  Midway cold = solve_midway(i, j, centre_line_start(i, j, length), length, tolerance);
  cold.iterations += warm_iterations;
  return contact_at(i, j, cold, length);
}

}  // namespace partimix::dem
