#include "sph/multi_material/material_rates.hpp"

#include <algorithm>
#include <cmath>

namespace partimix::sph {
namespace {

// Monaghan's Pi_ij (1992), 0 for receding pairs.
double artificial_viscosity(const MaterialParticles& p, std::size_t i, std::size_t j,
                            const Vec3& rij, double r2, double h, const ArtificialViscosity& av) {
  const double approach = (p.velocity[i] - p.velocity[j]).dot(rij);
  if (approach >= 0.0)
    return 0.0;
  const double mu = h * approach / (r2 + 0.01 * h * h);
  const double c = 0.5 * (p.sound_speed[i] + p.sound_speed[j]);
  const double rho = 0.5 * (p.density[i] + p.density[j]);
  return (-av.alpha * c * mu + av.beta * mu * mu) / rho;
}

// sigma / rho^2-like stress of particle k: -p I + S.
Mat3 stress(const MaterialParticles& p, std::size_t k) {
  return p.deviatoric_stress[k] - p.pressure[k] * Mat3::Identity();
}

// The pressure of particle k across a cut bond: max(p, 0), so that it pushes but never pulls.
double contact_pressure(const MaterialParticles& p, std::size_t k) {
  return std::max(p.pressure[k], 0.0);
}

// The artificial stress's pair weight f_ij^4, f_ij = W(r, h) / W(dp, h).
double repulsion_weight(const ScaledKernel& kernel, double r, double h, double spacing) {
  const double at_spacing = kernel.value(spacing, h);
  if (at_spacing <= 0.0)
    return 0.0;
  const double f = kernel.value(r, h) / at_spacing;
  return (f * f) * (f * f);
}

struct PairSums {
  Vec3 acceleration = Vec3::Zero();
  double expansion = 0.0;
  double heating = 0.0;
  Mat3 velocity_gradient = Mat3::Zero();
  Mat3 position_moment = Mat3::Zero();
  Vec3 unity_gradient = Vec3::Zero();
};

// A determinant of the moment B below this (1 on a full lattice) leaves the gradient uncorrected.
constexpr double kSmallestMoment = 0.1;

// The velocity gradient corrected to first order, L B^-1 with B = sum_j m_j / rho_j (x_j - x_i)
// (x) grad W-bar (Randles & Libersky 1996; Bonet & Lok 1999): exact for a linear velocity field
// whatever the neighbours, so that a free surface or a disordered lattice does not scatter the
// strain rate. In 2D B's z row and column are empty and its zz entry is set to 1. Where the
// neighbours are too few to invert B the gradient stays uncorrected.
Mat3 corrected_gradient(const Mat3& gradient, Mat3 moment) {
  if (moment(2, 2) == 0.0)
    moment(2, 2) = 1.0;
  if (std::abs(moment.determinant()) < kSmallestMoment)
    return gradient;
  return gradient * moment.inverse();
}

}  // namespace

void material_rates(const MaterialParticles& p, std::size_t count, const CellGrid& grid,
                    const ScaledKernel& kernel, DensityPairing pairing,
                    const ArtificialViscosity& av, const MaterialRates& rates) {
  const double support = kernel.support();
  const bool summation = pairing == DensityPairing::summation;
  const auto n = static_cast<std::ptrdiff_t>(count);
#pragma omp parallel for schedule(dynamic, 256)
  for (std::ptrdiff_t ii = 0; ii < n; ++ii) {
    const auto i = static_cast<std::size_t>(ii);
    const Mat3 sigma_i = stress(p, i);
    const bool i_stressed = !p.artificial_stress[i].isZero();
    const double own_weight = 1.0 / (p.omega[i] * p.density[i] * p.density[i]);
    PairSums sums;
    grid.for_each_neighbour(
        i, p.position,
        [&](std::size_t j, const Vec3& rij, double r2) {
          const double reach = support * std::max(p.h[i], p.h[j]);
          if (j == i || r2 >= reach * reach)
            return;
          const double r = std::sqrt(r2);
          const Vec3 unit = rij / r;
          const Vec3 grad_i = kernel.derivative(r, p.h[i]) * unit;
          const Vec3 grad_j = kernel.derivative(r, p.h[j]) * unit;
          const Vec3 grad = 0.5 * (grad_i + grad_j);
          const double h = 0.5 * (p.h[i] + p.h[j]);
          const Vec3 vij = p.velocity[i] - p.velocity[j];
          const double mj = p.mass[j];
          const double cross = 1.0 / (p.density[i] * p.density[j]);
          // An intact bond's stress force is the total Lagrangian one (total_lagrangian.hpp), a
          // cut one's is a contact.
          const Bond bond = p.bonds != nullptr ? p.bonds->state(i, j) : Bond::none;
          if (summation) {
            const double other_weight = 1.0 / (p.omega[j] * p.density[j] * p.density[j]);
            if (bond == Bond::none) {
              sums.acceleration +=
                  mj * (own_weight * sigma_i * grad_i + other_weight * stress(p, j) * grad_j);
            } else if (bond == Bond::cut) {
              sums.acceleration -= mj * (own_weight * contact_pressure(p, i) * grad_i +
                                         other_weight * contact_pressure(p, j) * grad_j);
            }
            sums.expansion += mj * own_weight * vij.dot(grad_i);
          } else {
            if (bond == Bond::none) {
              sums.acceleration += mj * cross * (sigma_i + stress(p, j)) * grad;
            } else if (bond == Bond::cut) {
              sums.acceleration -=
                  mj * cross * (contact_pressure(p, i) + contact_pressure(p, j)) * grad;
            }
            sums.expansion += mj * cross * vij.dot(grad);
          }
          const double pi = artificial_viscosity(p, i, j, rij, r2, h, av);
          sums.acceleration -= mj * pi * grad;
          // The artificial stress acts between solids only, and not between bonded ones; fluids
          // skip its two kernel lookups.
          if (bond == Bond::none && (i_stressed || !p.artificial_stress[j].isZero())) {
            const double dp = 0.5 * (p.spacing[i] + p.spacing[j]);
            sums.acceleration += mj * repulsion_weight(kernel, r, h, dp) *
                                 (p.artificial_stress[i] + p.artificial_stress[j]) * grad;
          }
          sums.heating += 0.5 * mj * pi * vij.dot(grad);
          const double viscous =
              mj * (p.viscosity[i] + p.viscosity[j]) * cross * rij.dot(grad) / (r2 + 0.01 * h * h);
          sums.acceleration += viscous * vij;
          sums.heating -= 0.5 * viscous * vij.squaredNorm();
          const double volume = mj / p.density[j];
          sums.velocity_gradient -= volume * vij * grad.transpose();
          sums.position_moment -= volume * rij * grad.transpose();
          sums.unity_gradient += volume * grad;
        },
        count);
    rates.acceleration[i] = sums.acceleration;
    rates.expansion[i] = sums.expansion;
    rates.heating[i] = sums.heating;
    rates.velocity_gradient[i] = corrected_gradient(sums.velocity_gradient, sums.position_moment);
    rates.unity_gradient[i] = sums.unity_gradient;
  }
}

}  // namespace partimix::sph
