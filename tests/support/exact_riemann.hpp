#pragma once
// The exact solution of the Riemann problem of the 1D Euler equations for an ideal gas with
// constant ratio of specific heats gamma (Toro 2009, "Riemann Solvers and Numerical Methods for
// Fluid Dynamics", chapter 4; docs/multi-material-sph.md, "Sod shock tube"):
// 1. the star pressure p* is the root of f(p) = f_L(p) + f_R(p) + u_R - u_L (section 4.2),
//    each f_K a shock branch (p > p_K) or a rarefaction branch (p <= p_K), found by Newton's
//    method from the two-rarefaction guess (section 4.3);
// 2. u* = (u_L + u_R + f_R(p*) - f_L(p*)) / 2 (section 4.2);
// 3. the state at x/t is sampled from the wave pattern (sections 4.4-4.5).
// Header-only, for the tests of the gas and multi-material SPH (the Sod shock tube).
#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace partimix::test_support {

struct GasState {
  double density;
  double velocity;
  double pressure;
};

class ExactRiemannSolver {
 public:
  // Throws std::invalid_argument when the data generate vacuum (the pressure positivity
  // condition of Toro's section 4.3 fails).
  ExactRiemannSolver(const GasState& left, const GasState& right, double gamma)
      : left_(left),
        right_(right),
        gamma_(gamma),
        left_sound_(std::sqrt(gamma * left.pressure / left.density)),
        right_sound_(std::sqrt(gamma * right.pressure / right.density)) {
    const double critical = 2.0 * (left_sound_ + right_sound_) / (gamma_ - 1.0);
    if (!(critical > right_.velocity - left_.velocity))
      throw std::invalid_argument("the Riemann data generate vacuum");
    solve_star();
  }

  double star_pressure() const { return star_pressure_; }
  double star_velocity() const { return star_velocity_; }
  // The densities either side of the contact: rho*_L and rho*_R.
  double star_left_density() const { return star_density(left_); }
  double star_right_density() const { return star_density(right_); }

  // The state at speed s = x / t from the initial discontinuity at x = 0.
  GasState sample(double speed) const {
    return speed <= star_velocity_ ? sample_side(left_, left_sound_, speed, 1.0)
                                   : sample_side(right_, right_sound_, speed, -1.0);
  }

 private:
  struct Branch {
    double value;
    double slope;
  };

  // f_K(p) and f_K'(p).
  Branch pressure_function(double p, const GasState& k, double sound) const {
    if (p > k.pressure) {
      const double a = 2.0 / ((gamma_ + 1.0) * k.density);
      const double b = (gamma_ - 1.0) / (gamma_ + 1.0) * k.pressure;
      const double root = std::sqrt(a / (p + b));
      return {(p - k.pressure) * root, root * (1.0 - 0.5 * (p - k.pressure) / (p + b))};
    }
    const double ratio = p / k.pressure;
    const double z = (gamma_ - 1.0) / (2.0 * gamma_);
    return {2.0 * sound / (gamma_ - 1.0) * (std::pow(ratio, z) - 1.0),
            std::pow(ratio, -(gamma_ + 1.0) / (2.0 * gamma_)) / (k.density * sound)};
  }

  // The two-rarefaction approximation: exact when both waves are rarefactions.
  double initial_guess() const {
    const double z = (gamma_ - 1.0) / (2.0 * gamma_);
    const double numerator =
        left_sound_ + right_sound_ - 0.5 * (gamma_ - 1.0) * (right_.velocity - left_.velocity);
    const double denominator =
        left_sound_ / std::pow(left_.pressure, z) + right_sound_ / std::pow(right_.pressure, z);
    return std::pow(numerator / denominator, 1.0 / z);
  }

  // Newton's method on f(p) = 0, stopped when the relative change 2 |dp| / (p_new + p_old) is
  // below 1e-15; f is increasing and concave, so Newton converges from any positive guess.
  void solve_star() {
    constexpr double kTolerance = 1.0e-15;
    const double du = right_.velocity - left_.velocity;
    double p = initial_guess();
    for (int i = 0; i < 100; ++i) {
      const Branch fl = pressure_function(p, left_, left_sound_);
      const Branch fr = pressure_function(p, right_, right_sound_);
      const double next =
          std::max(p - (fl.value + fr.value + du) / (fl.slope + fr.slope), kTolerance * p);
      const double change = 2.0 * std::abs(next - p) / (next + p);
      p = next;
      if (change <= kTolerance)
        break;
    }
    star_pressure_ = p;
    star_velocity_ =
        0.5 * (left_.velocity + right_.velocity + pressure_function(p, right_, right_sound_).value -
               pressure_function(p, left_, left_sound_).value);
  }

  // Behind a shock (the Rankine-Hugoniot density ratio) or a rarefaction (isentropic).
  double star_density(const GasState& k) const {
    const double ratio = star_pressure_ / k.pressure;
    if (ratio > 1.0) {
      const double g = (gamma_ - 1.0) / (gamma_ + 1.0);
      return k.density * (ratio + g) / (g * ratio + 1.0);
    }
    return k.density * std::pow(ratio, 1.0 / gamma_);
  }

  // One side of the contact; `sign` is +1 for the left wave, -1 for the right, so that the
  // left-side formulas serve both after mirroring velocities and speeds.
  GasState sample_side(const GasState& k, double sound, double speed, double sign) const {
    const double u = sign * k.velocity;  // mirrored: the wave of interest always moves left
    const double s = sign * speed;
    const double ratio = star_pressure_ / k.pressure;
    const GasState star{star_density(k), star_velocity_, star_pressure_};
    if (ratio > 1.0) {
      const double shock = u - sound * std::sqrt((gamma_ + 1.0) / (2.0 * gamma_) * ratio +
                                                 (gamma_ - 1.0) / (2.0 * gamma_));
      return s <= shock ? k : star;
    }
    const double head = u - sound;
    const double tail =
        sign * star_velocity_ - sound * std::pow(ratio, (gamma_ - 1.0) / (2.0 * gamma_));
    if (s <= head)
      return k;
    if (s >= tail)
      return star;
    // Inside the fan: the left fan's formulas, mirrored for the right.
    const double base = 2.0 / (gamma_ + 1.0) + (gamma_ - 1.0) / ((gamma_ + 1.0) * sound) * (u - s);
    const double fan_velocity = 2.0 / (gamma_ + 1.0) * (sound + 0.5 * (gamma_ - 1.0) * u + s);
    return {k.density * std::pow(base, 2.0 / (gamma_ - 1.0)), sign * fan_velocity,
            k.pressure * std::pow(base, 2.0 * gamma_ / (gamma_ - 1.0))};
  }

  GasState left_;
  GasState right_;
  double gamma_;
  double left_sound_;
  double right_sound_;
  double star_pressure_ = 0.0;
  double star_velocity_ = 0.0;
};

// The state at x / t of the Riemann problem (left | right) at x = 0, t = 0.
inline GasState sample_riemann(const GasState& left, const GasState& right, double gamma,
                               double x_over_t) {
  return ExactRiemannSolver(left, right, gamma).sample(x_over_t);
}

}  // namespace partimix::test_support
