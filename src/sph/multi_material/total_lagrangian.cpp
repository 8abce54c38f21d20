#include "sph/multi_material/total_lagrangian.hpp"

#include <Eigen/SVD>
#include <algorithm>
#include <cmath>

namespace partimix::sph {
namespace {

// Below this |det B| (1 on a full lattice) a particle has too few bonds to correct: B^-1 = I.
constexpr double kSmallestMoment = 1e-3;
// A particle that lost bonds to a crack fails when the smallest singular value of its B falls
// below this (1 on a full lattice, 0.5 at a straight free surface, 0.13-0.18 at the corners
// where a crack meets the droplet's shell surface; docs/multi-material-sph.md, "Cracks").
constexpr double kLeastLooseMoment = 0.1;

// A 2D tensor's empty zz entry set to 1, so that it inverts and its determinant is the area's.
Mat3 with_unit_zz(Mat3 m, int dimensions) {
  if (dimensions == 2)
    m(2, 2) = 1.0;
  return m;
}

}  // namespace

TotalLagrangianSolids::TotalLagrangianSolids(const Domain& domain, const ScaledKernel& kernel,
                                             double largest_h0)
    : kernel_(kernel),
      dimensions_(domain.dimensions),
      grid_(domain, kernel.support() * largest_h0) {}

// Calls fn(j, X_ij, grad0 W_ij) for every particle j whose bond to i is intact.
template <class Fn>
void TotalLagrangianSolids::for_each_bond(const BondedParticles& p, std::size_t i, Fn&& fn) const {
  bonds_.for_each_intact(i, [&](std::size_t j) {
    const Vec3 xij = p.reference[i] - p.reference[j];
    const double r = xij.norm();
    const double h = 0.5 * (p.reference_h[i] + p.reference_h[j]);
    fn(j, xij, (kernel_.derivative(r, h) / r) * xij);
  });
}

// Calls fn(i) for every particle of [0, count) bonded now, in parallel.
template <class Fn>
void TotalLagrangianSolids::for_each_bonded(const BondedParticles& p, std::size_t count,
                                            Fn&& fn) const {
  const auto n = static_cast<std::ptrdiff_t>(count);
#pragma omp parallel for schedule(dynamic, 256)
  for (std::ptrdiff_t ii = 0; ii < n; ++ii) {
    const auto i = static_cast<std::size_t>(ii);
    if (holds(p, i))
      fn(i);
  }
}

void TotalLagrangianSolids::refer(const BondedParticles& p, std::size_t count) {
  grid_.build(p.reference);
  bonds_.build(grid_, p.reference, p.reference_h, p.bonded, kernel_.support());
  deformation_.assign(count, Mat3::Identity());
  velocity_gradient_.assign(count, Mat3::Zero());
  loosened_.clear();
  for (std::size_t k = 0; k < std::min(count, p.damage.size()); ++k) {
    if (p.bonded[k] && p.damage[k] >= 1.0)
      fail(p, k);
  }
  take_corrections(p, count);
}

void TotalLagrangianSolids::crack(const BondedParticles& p, std::size_t count) {
  loosened_.clear();
  bool cracked = false;
  for (std::size_t k = 0; k < std::min(count, p.damage.size()); ++k) {
    if (holds(p, k) && p.damage[k] >= 1.0) {
      fail(p, k);
      cracked = true;
    }
  }
  if (cracked)
    take_corrections(p, count);
}

// Fails particle k, whose crack is the disc of half its reference spacing, (V0 / depth)^(1/d) / 2.
void TotalLagrangianSolids::fail(const BondedParticles& p, std::size_t k) {
  const double spacing = std::pow(p.reference_volume[k], 1.0 / dimensions_);
  bonds_.fail(k, p.reference, 0.5 * spacing);
  deformation_[k] = Mat3::Identity();
  velocity_gradient_[k] = Mat3::Zero();
}

// Each bonded particle's B^-1 from its intact bonds. A particle that lost bonds to a crack and
// whose B has a singular value below kLeastLooseMoment fails too (it is loosened), and B^-1 is
// taken again, until none is loose: failing only cuts bonds, which only lowers B, so the
// particles loosened depend on which have failed, not on the order.
void TotalLagrangianSolids::take_corrections(const BondedParticles& p, std::size_t count) {
  for (;;) {
    correction_.assign(count, Mat3::Identity());
    loose_.assign(count, 0);
    for_each_bonded(p, count, [&](std::size_t i) {
      Mat3 moment = Mat3::Zero();
      for_each_bond(p, i, [&](std::size_t j, const Vec3& reference_ij, const Vec3& grad) {
        moment -= p.reference_volume[j] * reference_ij * grad.transpose();
      });
      moment = with_unit_zz(moment, dimensions_);
      if (bonds_.lost_bonds(i) &&
          Eigen::JacobiSVD<Mat3>(moment).singularValues().minCoeff() < kLeastLooseMoment)
        loose_[i] = 1;
      else if (std::abs(moment.determinant()) >= kSmallestMoment)
        correction_[i] = moment.inverse();
    });
    const std::size_t before = loosened_.size();
    for (std::size_t k = 0; k < count; ++k) {
      if (loose_[k]) {
        fail(p, k);
        loosened_.push_back(k);
      }
    }
    if (loosened_.size() == before)
      return;
  }
}

void TotalLagrangianSolids::deform(const BondedParticles& p, std::size_t count) {
  for_each_bonded(p, count, [&](std::size_t i) {
    Mat3 stretch = Mat3::Zero();
    Mat3 rate = Mat3::Zero();
    for_each_bond(p, i, [&](std::size_t j, const Vec3&, const Vec3& grad) {
      const double volume = p.reference_volume[j];
      stretch += volume * (p.position[j] - p.position[i]) * grad.transpose();
      rate += volume * (p.velocity[j] - p.velocity[i]) * grad.transpose();
    });
    deformation_[i] = with_unit_zz(stretch * correction_[i], dimensions_);
    velocity_gradient_[i] = (rate * correction_[i]) * deformation_[i].inverse();
  });
}

void TotalLagrangianSolids::add_forces(const BondedParticles& p, std::size_t count,
                                       std::span<Vec3> acceleration) {
  piola_.assign(count, Mat3::Zero());
  for (std::size_t i = 0; i < count; ++i) {
    if (!holds(p, i))
      continue;
    const Mat3& f = deformation_[i];
    piola_[i] = f.determinant() * p.stress[i] * f.inverse().transpose();
  }
  for_each_bonded(p, count, [&](std::size_t i) {
    Vec3 force = Vec3::Zero();
    for_each_bond(p, i, [&](std::size_t j, const Vec3& reference_ij, const Vec3& grad) {
      const double volumes = p.reference_volume[i] * p.reference_volume[j];
      force += volumes * (piola_[i] + piola_[j]) * grad;
      const Vec3 xij = p.position[i] - p.position[j];
      const double r = xij.norm();
      if (r == 0.0)
        return;
      const Vec3 unit = xij / r;
      const Vec3 error = (deformation_[i] + deformation_[j]) * reference_ij - 2.0 * xij;
      const double r0 = reference_ij.norm();
      const double h = 0.5 * (p.reference_h[i] + p.reference_h[j]);
      const double stiffness = 0.5 * (p.hourglass[i] + p.hourglass[j]);
      force +=
          0.5 * stiffness * volumes * kernel_.value(r0, h) / (r0 * r0) * error.dot(unit) * unit;
    });
    acceleration[i] += force / p.mass[i];
  });
}

}  // namespace partimix::sph
