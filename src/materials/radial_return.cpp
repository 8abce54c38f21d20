#include "materials/radial_return.hpp"

#include <cmath>

namespace partimix::materials {
namespace {

constexpr int kMaxIterations = 100;  // bisection alone halves the bracket to round-off in ~60
constexpr double kRelativeTolerance = 1.0e-14;

// Solves f(dr) = sigma_trial - 3 G dr - sigma_y(dr) = 0 with f(0) > 0: a Newton step where it
// stays inside the bracket [low, high] of the root, a bisection otherwise.
double consistent_increment(double trial, double shear_modulus, const YieldFunction& yield) {
  double low = 0.0;
  double high = trial / (3.0 * shear_modulus);
  double dr = 0.0;
  for (int i = 0; i < kMaxIterations; ++i) {
    const YieldPoint point = yield(dr);
    const double residual = trial - 3.0 * shear_modulus * dr - point.stress;
    if (std::abs(residual) <= kRelativeTolerance * trial)
      return dr;
    (residual > 0.0 ? low : high) = dr;
    const double newton = dr + residual / (3.0 * shear_modulus + point.slope);
    dr = (newton > low && newton < high) ? newton : 0.5 * (low + high);
    if (high - low <= kRelativeTolerance * high)
      return dr;
  }
  return dr;
}

}  // namespace

double von_mises_stress(const Mat3& deviatoric_stress) {
  return std::sqrt(1.5 * deviatoric_stress.squaredNorm());
}

RadialReturnResult radial_return(const Mat3& trial_deviatoric_stress, double shear_modulus,
                                 const YieldFunction& yield) {
  const double trial = von_mises_stress(trial_deviatoric_stress);
  if (trial <= yield(0.0).stress)
    return {trial_deviatoric_stress, 0.0};
  const double dr = consistent_increment(trial, shear_modulus, yield);
  return {trial_deviatoric_stress * (yield(dr).stress / trial), dr};
}

// The linear case in closed form; scaling by sigma_y(dr) / sigma_eq_trial rather than by
// 1 - 3 G dr / sigma_eq_trial lands the stress on the yield surface to round-off.
RadialReturnResult radial_return(const Mat3& trial_deviatoric_stress, double shear_modulus,
                                 double yield_stress, double hardening_modulus) {
  const double trial = von_mises_stress(trial_deviatoric_stress);
  if (trial <= yield_stress)
    return {trial_deviatoric_stress, 0.0};
  const double dr = (trial - yield_stress) / (3.0 * shear_modulus + hardening_modulus);
  const double yield = yield_stress + hardening_modulus * dr;
  return {trial_deviatoric_stress * (yield / trial), dr};
}

}  // namespace partimix::materials
