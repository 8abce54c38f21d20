#include "sph/multi_material/solid_update.hpp"

#include <algorithm>
#include <cmath>

#include "materials/johnson_cook.hpp"
#include "materials/radial_return.hpp"

namespace partimix::sph {

SolidStepResult return_to_yield(const SolidSpec& solid, const Mat3& trial, double pressure,
                                double temperature, double density, double dt, SolidPoint& point) {
  // A fully damaged point carries no deviatoric stress, whatever its flow stress (an infinite
  // one, a solid that never yields, would give 0 x inf).
  if (point.damage >= 1.0) {
    point.deviatoric_stress.setZero();
    return {};
  }
  const materials::JohnsonCookParameters& jc = solid.johnson_cook;
  // The yield function's state, which its closure holds by one reference: small enough for
  // std::function to keep without allocating.
  struct YieldState {
    const materials::JohnsonCookParameters& jc;
    double intact;
    double plastic_strain;
    double temperature;
    double dt;
  } const state{jc, 1.0 - point.damage, point.plastic_strain, temperature, dt};
  const double r = point.plastic_strain;
  // sigma_y(r + dr) (1 - D) at the rate dr / dt; its slope by a forward difference in dr, as the
  // rate term's derivative at dr = 0 is unbounded.
  auto yield = [&state](double dr) {
    const double stress = state.intact * materials::flow_stress(state.jc, state.plastic_strain + dr,
                                                                dr / state.dt, state.temperature);
    const double step = std::max(1e-9, 1e-6 * dr);
    const double ahead =
        state.intact * materials::flow_stress(state.jc, state.plastic_strain + dr + step,
                                              (dr + step) / state.dt, state.temperature);
    return materials::YieldPoint{stress, (ahead - stress) / step};
  };
  const materials::RadialReturnResult returned =
      materials::radial_return(trial, solid.shear_modulus, yield);
  point.deviatoric_stress = returned.deviatoric_stress;
  const double dr = returned.plastic_strain_increment;
  SolidStepResult result{dr, 0.0};
  if (dr <= 0.0)
    return result;
  const double equivalent = materials::von_mises_stress(returned.deviatoric_stress);
  result.plastic_work = equivalent * dr / density;
  const double triaxiality = equivalent > 0.0 ? -pressure / equivalent : 0.0;
  const double failure = materials::failure_strain(jc, triaxiality, dr / dt, temperature);
  point.damage = materials::damage_after_step(jc, point.damage, r, dr, failure);
  point.plastic_strain = r + dr;
  if (point.damage >= 1.0)
    point.deviatoric_stress.setZero();
  return result;
}

}  // namespace partimix::sph
