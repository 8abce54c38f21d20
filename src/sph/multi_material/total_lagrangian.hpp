#pragma once
// Total Lagrangian solids of the multi-material SPH scheme (docs/multi-material-sph.md, "Total
// Lagrangian solids"): the particles of solids with `formulation: total_lagrangian` are bonded
// to those within the kernel's support in the reference configuration X (their positions at the
// start), and a bonded pair's stress force uses the kernel gradient at X, which never changes:
// there is no tensile instability (Belytschko, Guo, Liu & Xiao 2000; Vignjevic, Reveles &
// Campbell 2006). With V0 = m / rho0, grad0 W_ij = dW/dr (|X_ij|, h0_ij) X_ij / |X_ij| and
// X_ij = X_i - X_j, for bonded i:
//   B_i = sum_j V0_j (X_j - X_i) (x) grad0 W_ij                  (first-order correction)
//   F_i = [sum_j V0_j (x_j - x_i) (x) grad0 W_ij] B_i^-1,   dF_i/dt the same with v,
//   L_i = dF_i/dt F_i^-1                                          (the velocity gradient)
//   m_i dv_i/dt += sum_j V0_i V0_j (P_i + P_j) grad0 W_ij,   P = J sigma F^-T
// (Ganzenmueller 2015, Comput. Methods Appl. Mech. Engrg. 286; the momentum with the plain
// reference gradient, so that for small strains it is the updated Lagrangian pair force and adds
// up with a liquid's pairs at an interface), and against the zero-energy modes the same paper's
// hourglass penalty, with x_ij = x_i - x_j, delta_ij^k = (F_k X_ij - x_ij) . x_ij / |x_ij| and
// c_ij the mean of the two particles' hourglass stiffnesses c = alpha E:
//   m_i dv_i/dt += 1/2 c_ij V0_i V0_j W0_ij / |X_ij|^2 (delta_ij^i + delta_ij^j) x_ij / |x_ij|.
// In 2D B and F have 1 at zz; B is inverted wherever |det B| >= 1e-3. The solver takes a bonded
// particle's density from F, rho = m / (V0 det F). The bonds are bond_table.hpp's: a fully damaged
// particle fails, its bonds and those across it are cut, and B, F and the forces then take the
// intact bonds alone; a particle a crack leaves too few bonds to span the space (a singular
// value of B below 0.1) fails as well. A failed particle has F = I and L = 0 here and is updated
// Lagrangian in the solver. The pairs of other particles stay updated Lagrangian, and cut bonds act
// by contact alone (sph/multi_material/material_rates.hpp). Needs a domain without periodic axes.
#include <cstdint>
#include <span>
#include <vector>

#include "core/vec.hpp"
#include "particles/cell_grid.hpp"
#include "sph/multi_material/bond_table.hpp"
#include "sph/scaled_kernel.hpp"

namespace partimix::sph {

struct BondedParticles {
  std::span<const Vec3> position;
  std::span<const Vec3> velocity;
  std::span<const Vec3> reference;  // X, the positions at the start
  std::span<const double> mass;
  std::span<const double> reference_volume;  // V0 = m / rho0
  std::span<const double> reference_h;       // h0
  std::span<const std::uint8_t> bonded;      // 1: a particle of a total Lagrangian solid
  std::span<const Mat3> stress;              // Cauchy sigma [Pa]
  std::span<const double> hourglass;         // c = alpha E [Pa]
  std::span<const double> damage;            // a particle at 1 fails; empty: none has
};

class TotalLagrangianSolids {
 public:
  // largest_h0: the largest reference smoothing length, for the reference configuration's grid.
  TotalLagrangianSolids(const Domain& domain, const ScaledKernel& kernel, double largest_h0);

  // Lays out the reference positions' grid and the bonds, fails the fully damaged particles and
  // takes each bonded particle's B^-1: once, and again when the particles are restored (which
  // bonds are cut follows from the damage alone).
  void refer(const BondedParticles& p, std::size_t count);
  // Fails the particles that became fully damaged since the last call and takes B^-1 again from
  // the intact bonds, failing the particles a crack left too few bonds (loosened()); after each
  // step's damage.
  void crack(const BondedParticles& p, std::size_t count);
  // The particles the last refer() or crack() failed for want of bonds, not of damage; the
  // solver treats them as fully damaged, their damage left as it was.
  std::span<const std::size_t> loosened() const { return loosened_; }
  // Whether particle i has failed, by damage or for want of bonds.
  bool failed(std::size_t i) const { return bonds_.failed(i); }
  // F and L of the bonded particles of [0, count); after refer().
  void deform(const BondedParticles& p, std::size_t count);
  // The bonded pairs' stress and hourglass forces, added to acceleration; after deform().
  void add_forces(const BondedParticles& p, std::size_t count, std::span<Vec3> acceleration);

  const BondTable& bonds() const { return bonds_; }
  // Whether particle i is bonded now: flagged, and not failed.
  bool holds(const BondedParticles& p, std::size_t i) const {
    return p.bonded[i] && !bonds_.failed(i);
  }
  // F and L after deform(), I and 0 for particles that are not bonded.
  std::span<const Mat3> deformation_gradient() const { return deformation_; }
  std::span<const Mat3> velocity_gradient() const { return velocity_gradient_; }

 private:
  template <class Fn>
  void for_each_bonded(const BondedParticles& p, std::size_t count, Fn&& fn) const;
  template <class Fn>
  void for_each_bond(const BondedParticles& p, std::size_t i, Fn&& fn) const;
  void fail(const BondedParticles& p, std::size_t k);
  void take_corrections(const BondedParticles& p, std::size_t count);

  const ScaledKernel& kernel_;
  int dimensions_;
  CellGrid grid_;  // of the reference positions
  BondTable bonds_;
  std::vector<Mat3> deformation_;        // F
  std::vector<Mat3> velocity_gradient_;  // L
  std::vector<Mat3> correction_;         // B^-1
  std::vector<std::uint8_t> loose_;      // take_corrections()' particles to fail
  std::vector<std::size_t> loosened_;
  std::vector<Mat3> piola_;  // P = J sigma F^-T
};

}  // namespace partimix::sph
