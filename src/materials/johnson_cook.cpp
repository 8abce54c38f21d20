#include "materials/johnson_cook.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace partimix::materials {

double dimensionless_strain_rate(const JohnsonCookParameters& p, double plastic_strain_rate) {
  return std::max(plastic_strain_rate / p.reference_strain_rate, 1.0);
}

double homologous_temperature(const JohnsonCookParameters& p, double temperature) {
  const double t = (temperature - p.room_temperature) / (p.melt_temperature - p.room_temperature);
  return std::clamp(t, 0.0, 1.0);
}

// Johnson & Cook 1983 (the seed's eq. 11 without 1 - D); pow(0, n) = 0 for n > 0 gives sigma_y = A
// at r = 0.
double flow_stress(const JohnsonCookParameters& p, double plastic_strain,
                   double plastic_strain_rate, double temperature) {
  const double hardening = p.A + p.B * std::pow(plastic_strain, p.n);
  const double rate = 1.0 + p.C * std::log(dimensionless_strain_rate(p, plastic_strain_rate));
  const double softening = 1.0 - std::pow(homologous_temperature(p, temperature), p.m);
  return hardening * rate * softening;
}

// Johnson & Cook 1985 (the seed's eq. 13).
double failure_strain(const JohnsonCookParameters& p, double stress_triaxiality,
                      double plastic_strain_rate, double temperature) {
  const double stress = p.D1 + p.D2 * std::exp(p.D3 * stress_triaxiality);
  const double rate = 1.0 + p.D4 * std::log(dimensionless_strain_rate(p, plastic_strain_rate));
  const double thermal = 1.0 + p.D5 * homologous_temperature(p, temperature);
  return stress * rate * thermal;
}

// The seed's eq. 12.
double damage_rate(const JohnsonCookParameters& p, double plastic_strain,
                   double plastic_strain_rate, double failure_strain) {
  if (plastic_strain <= p.damage_threshold || !(plastic_strain_rate > 0.0))
    return 0.0;
  const double span = failure_strain - p.damage_threshold;
  if (!(span > 0.0))
    return std::numeric_limits<double>::infinity();
  return p.critical_damage / span * plastic_strain_rate;
}

double damage_after_step(const JohnsonCookParameters& p, double damage, double plastic_strain,
                         double plastic_strain_increment, double failure_strain) {
  const double start = std::max(plastic_strain, p.damage_threshold);
  const double beyond = plastic_strain + plastic_strain_increment - start;
  if (!(beyond > 0.0))
    return std::min(damage, 1.0);
  const double span = failure_strain - p.damage_threshold;
  if (!(span > 0.0))
    return 1.0;
  return std::min(damage + p.critical_damage * beyond / span, 1.0);
}

}  // namespace partimix::materials
