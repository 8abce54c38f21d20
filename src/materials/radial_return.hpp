#pragma once
// The J2 radial return (Wilkins 1964; Simo & Hughes 1998, box 3.2; docs/multi-material-sph.md,
// "Radial return"): a trial deviatoric stress S_trial outside the von Mises yield surface is
// scaled back onto it along itself. The plastic strain increment dr solves the consistency
// condition
//   sigma_eq_trial - 3 G dr = sigma_y(dr),  sigma_eq_trial = sqrt(3/2 S_trial : S_trial),
// and the returned stress is S_trial sigma_y(dr) / sigma_eq_trial, deviatoric and coaxial with
// S_trial. The yield stress is a function of the increment, so that the caller's closure can
// hold the state it depends on: sigma_y(r + dr) for strain hardening, and for Johnson-Cook
// also the plastic strain rate dr / dt and the temperature.
#include <functional>

#include "core/vec.hpp"

namespace partimix::materials {

// The yield stress [Pa] at a trial plastic strain increment dr, and its slope
// d sigma_y / d(dr) [Pa] (the hardening modulus H for strain hardening).
struct YieldPoint {
  double stress = 0.0;
  double slope = 0.0;
};
using YieldFunction = std::function<YieldPoint(double plastic_strain_increment)>;

struct RadialReturnResult {
  Mat3 deviatoric_stress;                 // [Pa]
  double plastic_strain_increment = 0.0;  // dr >= 0 [-]
};

// The von Mises equivalent stress sqrt(3/2 S : S) [Pa] of a deviatoric stress.
double von_mises_stress(const Mat3& deviatoric_stress);

// Returns S_trial unchanged with dr = 0 when sigma_eq_trial <= sigma_y(0); otherwise solves the
// consistency condition by Newton's method in dr, safeguarded by bisection on the bracket
// [0, sigma_eq_trial / (3 G)] (which holds the root for any sigma_y >= 0, even with an infinite
// slope at dr = 0 as in a power law with n < 1). S_trial is symmetric and traceless, G > 0.
RadialReturnResult radial_return(const Mat3& trial_deviatoric_stress, double shear_modulus,
                                 const YieldFunction& yield);

// Linear hardening sigma_y(dr) = yield_stress + hardening_modulus dr, with the closed form
// dr = (sigma_eq_trial - sigma_y) / (3 G + H); H = 0 is perfect plasticity.
RadialReturnResult radial_return(const Mat3& trial_deviatoric_stress, double shear_modulus,
                                 double yield_stress, double hardening_modulus);

}  // namespace partimix::materials
