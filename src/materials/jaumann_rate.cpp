#include "materials/jaumann_rate.hpp"

namespace partimix::materials {

Mat3 jaumann_stress_rate(const Mat3& s, const Mat3& l, double shear_modulus) {
  const Mat3 strain_rate = 0.5 * (l + l.transpose());
  const Mat3 spin = 0.5 * (l - l.transpose());
  const Mat3 deviatoric_rate = strain_rate - strain_rate.trace() / 3.0 * Mat3::Identity();
  return 2.0 * shear_modulus * deviatoric_rate + s * spin.transpose() + spin * s;
}

}  // namespace partimix::materials
