#include "core/bicgstab.hpp"

#include <cmath>
#include <limits>

namespace partimix {

namespace {
// r0 . r below this fraction of |r0|^2: the residual has become orthogonal to the shadow vector
// and the recurrence has lost its direction (the test of Eigen's BiCGSTAB, eps^2).
constexpr double kOrthogonal =
    std::numeric_limits<double>::epsilon() * std::numeric_limits<double>::epsilon();
}  // namespace

Bicgstab::Bicgstab(double tolerance, int max_iterations)
    : tolerance_(tolerance), max_iterations_(max_iterations) {}

void Bicgstab::restart(const Matrix& a, const Vector& b, const Vector& x) {
  r_ = b;
  r_.noalias() -= a * x;
  shadow_ = r_;
  p_.setZero(b.size());
  v_.setZero(b.size());
  rho_ = alpha_ = omega_ = 1.0;
}

LinearSolve Bicgstab::solve(const Matrix& a, const Preconditioner& m, const Vector& b, Vector& x) {
  const double b_norm2 = b.squaredNorm();
  if (b_norm2 == 0.0) {
    x.setZero(b.size());
    return {0, 0.0, true};
  }
  const double target = tolerance_ * tolerance_ * b_norm2;
  restart(a, b, x);
  if (r_.squaredNorm() > b_norm2) {
    x.setZero(b.size());
    restart(a, b, x);
  }
  int iteration = 0;
  while (r_.squaredNorm() > target && iteration < max_iterations_) {
    double rho = shadow_.dot(r_);
    if (std::abs(rho) < kOrthogonal * shadow_.squaredNorm()) {
      restart(a, b, x);
      rho = shadow_.dot(r_);
    }
    const double beta = (rho / rho_) * (alpha_ / omega_);
    rho_ = rho;
    p_ = r_ + beta * (p_ - omega_ * v_);
    m.apply(p_, y_);
    v_.noalias() = a * y_;
    const double shadow_v = shadow_.dot(v_);
    ++iteration;
    if (shadow_v == 0.0) {
      restart(a, b, x);
      continue;
    }
    alpha_ = rho_ / shadow_v;
    s_ = r_ - alpha_ * v_;
    m.apply(s_, z_);
    t_.noalias() = a * z_;
    const double t_norm2 = t_.squaredNorm();
    omega_ = t_norm2 > 0.0 ? t_.dot(s_) / t_norm2 : 0.0;
    x += alpha_ * y_ + omega_ * z_;
    r_ = s_ - omega_ * t_;
    if (omega_ == 0.0)
      restart(a, b, x);
  }
  const double residual = std::sqrt(r_.squaredNorm() / b_norm2);
  return {iteration, residual, residual <= tolerance_};
}

}  // namespace partimix
