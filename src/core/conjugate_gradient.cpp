#include "core/conjugate_gradient.hpp"

#include <cmath>

namespace partimix {

ConjugateGradient::ConjugateGradient(double tolerance, int max_iterations)
    : tolerance_(tolerance), max_iterations_(max_iterations) {}

void ConjugateGradient::compute(const Matrix& a) {
  inverse_diagonal_.resize(a.rows());
  for (Eigen::Index i = 0; i < a.rows(); ++i) {
    const double d = a.coeff(i, i);
    inverse_diagonal_[i] = d != 0.0 ? 1.0 / d : 1.0;
  }
}

LinearSolve ConjugateGradient::solve(const Matrix& a, const Eigen::Ref<const Vector>& b,
                                     Vector& x) {
  const double b_norm2 = b.squaredNorm();
  if (b_norm2 == 0.0) {
    x.setZero(b.size());
    return {0, 0.0, true};
  }
  const double target = tolerance_ * tolerance_ * b_norm2;
  r_ = b;
  r_.noalias() -= a * x;
  if (r_.squaredNorm() > b_norm2) {
    x.setZero(b.size());
    r_ = b;
  }
  z_ = inverse_diagonal_.cwiseProduct(r_);
  p_ = z_;
  double rz = r_.dot(z_);
  int iteration = 0;
  while (r_.squaredNorm() > target && iteration < max_iterations_) {
    q_.noalias() = a * p_;
    const double pq = p_.dot(q_);
    ++iteration;
    if (pq <= 0.0)
      break;  // not positive definite along p: no step reduces the error
    const double alpha = rz / pq;
    x += alpha * p_;
    r_ -= alpha * q_;
    z_ = inverse_diagonal_.cwiseProduct(r_);
    const double rz_next = r_.dot(z_);
    p_ = z_ + (rz_next / rz) * p_;
    rz = rz_next;
  }
  const double residual = std::sqrt(r_.squaredNorm() / b_norm2);
  return {iteration, residual, residual <= tolerance_};
}

}  // namespace partimix
