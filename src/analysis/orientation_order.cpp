#include "analysis/orientation_order.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include "core/error.hpp"

namespace partimix::analysis {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The index of the only coefficient equal to `extreme`, or -1 when two share it.
int only(const Vec3& values, double extreme) {
  int found = -1;
  for (int k = 0; k < 3; ++k) {
    if (values[k] == extreme) {
      if (found >= 0)
        return -1;
      found = k;
    }
  }
  return found;
}

template <class Field>
const Field& required(const Field* field) {
  if (field == nullptr) {
    throw RunError(
        "the analysis orientation_order needs the particle fields orientation_w, orientation_v "
        "and half_axes (DEM grains of a species with a shape); these particles lack one");
  }
  return *field;
}

// The largest eigenvalue of Q = (3 <u u^T> - I) / 2 from the sum of u u^T over `count` grains.
double largest_order_eigenvalue(const Mat3& sum_uu, double count) {
  const Mat3 order = (3.0 * sum_uu / count - Mat3::Identity()) / 2.0;
  const Eigen::SelfAdjointEigenSolver<Mat3> solver(order, Eigen::EigenvaluesOnly);
  return solver.eigenvalues()(2);
}

}  // namespace

int grain_axis(const Vec3& half_axes) {
  const int longest = only(half_axes, half_axes.maxCoeff());
  return longest >= 0 ? longest : only(half_axes, half_axes.minCoeff());
}

// Grain i's velocity, relative to the rotating frame when there is one: v - omega x (x - p).
Vec3 OrientationOrder::velocity_of(const ParticleStore& particles, std::size_t i) const {
  const Vec3& velocity = particles.velocity()[i];
  if (!reference_.rotating_frame)
    return velocity;
  const Vec3 arm = particles.position()[i] - reference_.frame_point;
  return velocity - reference_.frame_angular_velocity.cross(arm);
}

OrientationOrder::OrientationOrder(const OrientationReference& reference)
    : reference_(reference), alignment_(kNaN), nematic_order_(kNaN) {
  if (!reference.velocity && !(reference.direction.norm() > 0.0))
    throw std::invalid_argument("orientation_order: the direction must not be zero");
  if (!(reference.min_speed >= 0.0))
    throw std::invalid_argument("orientation_order: min_speed must not be negative");
  if (reference.rotating_frame && !(reference.velocity && reference.frame_point.allFinite() &&
                                    reference.frame_angular_velocity.allFinite())) {
    throw std::invalid_argument(
        "orientation_order: a rotating frame needs the velocity as reference and finite values");
  }
  reference_.direction.normalize();
}

void OrientationOrder::sample(const ParticleStore& particles, double /*time*/,
                              std::span<double> values) {
  const auto& w = required(particles.find_scalar("orientation_w")).values;
  const auto& v = required(particles.find_vector("orientation_v")).values;
  const auto& half_axes = required(particles.find_vector("half_axes")).values;
  Mat3 sum_uu = Mat3::Zero();
  double with_axis = 0.0;
  double sum_p2 = 0.0;
  double with_reference = 0.0;
  for (std::size_t i = 0; i < particles.size(); ++i) {
    const int axis = grain_axis(half_axes[i]);
    if (!particles.is_material(i) || axis < 0)
      continue;
    const Eigen::Quaterniond q(w[i], v[i].x(), v[i].y(), v[i].z());
    const Vec3 u = q.toRotationMatrix().col(axis);
    sum_uu += u * u.transpose();
    with_axis += 1.0;
    const Vec3 velocity = velocity_of(particles, i);
    const double speed = velocity.norm();
    if (reference_.velocity && !(speed > reference_.min_speed && speed > 0.0))
      continue;
    const double cosine =
        u.dot(reference_.velocity ? Vec3(velocity / speed) : reference_.direction);
    sum_p2 += 0.5 * (3.0 * cosine * cosine - 1.0);
    with_reference += 1.0;
  }
  alignment_ = with_reference > 0.0 ? sum_p2 / with_reference : kNaN;
  nematic_order_ = with_axis > 0.0 ? largest_order_eigenvalue(sum_uu, with_axis) : kNaN;
  values[0] = alignment_;
  values[1] = nematic_order_;
}

void OrientationOrder::replay(double /*time*/, std::span<const double> values) {
  alignment_ = values[0];
  nematic_order_ = values[1];
}

void OrientationOrder::add_figures(Figures& figures) const {
  if (std::isfinite(alignment_))
    figures.add("alignment_final", alignment_, "");
  if (std::isfinite(nematic_order_))
    figures.add("nematic_order_final", nematic_order_, "");
}

}  // namespace partimix::analysis
