#pragma once
// The Johnson-Cook strength and damage model of the gel shell (docs/multi-material-sph.md,
// "Johnson-Cook strength and damage"; the seed's eqs. 11-13):
// - flow stress (Johnson & Cook 1983): sigma_y = [A + B r^n][1 + C ln rate*][1 - T*^m];
// - failure strain (Johnson & Cook 1985): p_f = [D1 + D2 exp(D3 sigma*)][1 + D4 ln rate*]
//   [1 + D5 T*], sigma* = sigma_m / sigma_eq the stress triaxiality;
// - damage (the seed's eq. 12): dD/dt = 0 while r <= p_d, else D_C / (p_f - p_d) dr/dt,
//   capped at D = 1.
// Here r is the accumulated equivalent plastic strain, rate* = max(rate / rate0, 1) the
// dimensionless plastic strain rate (clamped at 1 so that ln rate* >= 0: below the reference
// rate neither the strength nor the failure strain falls), and T* = (T - T_room) /
// (T_melt - T_room) the homologous temperature clamped to [0, 1]. The (1 - D) factor of the
// seed's eq. 11 is left to the caller.

namespace partimix::materials {

struct JohnsonCookParameters {
  double A = 0.0;                      // yield stress [Pa]
  double B = 0.0;                      // hardening modulus [Pa]
  double n = 1.0;                      // hardening exponent [-]
  double C = 0.0;                      // strain-rate coefficient [-]
  double m = 1.0;                      // thermal-softening exponent [-]
  double reference_strain_rate = 1.0;  // rate0 [1/s]
  double room_temperature = 294.0;     // T_room [K]
  double melt_temperature = 1000.0;    // T_melt [K]
  double D1 = 0.0;                     // failure-strain constants [-]
  double D2 = 0.0;
  double D3 = 0.0;
  double D4 = 0.0;
  double D5 = 0.0;
  double damage_threshold = 0.0;  // p_d: plastic strain at which damage starts [-]
  double critical_damage = 1.0;   // D_C: damage reached at the failure strain [-]
};

// rate* = max(plastic_strain_rate / reference_strain_rate, 1) [-].
double dimensionless_strain_rate(const JohnsonCookParameters& p, double plastic_strain_rate);

// T* = (T - T_room) / (T_melt - T_room), clamped to [0, 1].
double homologous_temperature(const JohnsonCookParameters& p, double temperature);

// sigma_y [Pa] at plastic strain r >= 0, plastic strain rate [1/s] and temperature [K].
double flow_stress(const JohnsonCookParameters& p, double plastic_strain,
                   double plastic_strain_rate, double temperature);

// p_f [-] at stress triaxiality sigma* = sigma_m / sigma_eq [-], plastic strain rate [1/s] and
// temperature [K].
double failure_strain(const JohnsonCookParameters& p, double stress_triaxiality,
                      double plastic_strain_rate, double temperature);

// dD/dt [1/s] at plastic strain r, plastic strain rate [1/s] and failure strain p_f. Once past
// p_d with p_f <= p_d, any further plastic flow fails the material at once: +infinity.
double damage_rate(const JohnsonCookParameters& p, double plastic_strain,
                   double plastic_strain_rate, double failure_strain);

// The damage after a step that takes the plastic strain from r to r + dr (dr >= 0) at failure
// strain p_f: D + D_C / (p_f - p_d) times the part of [r, r + dr] beyond p_d, capped at 1. The
// exact integral of damage_rate() over the step, so the damage reaches D_C exactly at r = p_f
// whatever the steps.
double damage_after_step(const JohnsonCookParameters& p, double damage, double plastic_strain,
                         double plastic_strain_increment, double failure_strain);

}  // namespace partimix::materials
