#pragma once
// The variable smoothing length (docs/multi-material-sph.md, "Variable smoothing length";
// Springel & Hernquist 2002; Price 2012, J. Comput. Phys. 231, 759, section 2.6; the seed's
// eqs. 8-9): each particle's h_i and summation density rho_i solve together
//   rho_i = sum_j m_j W(r_ij, h_i),   h_i = eta (m_i / rho_i)^(1/d),
// by Newton's method in h_i, and the grad-h term
//   Omega_i = 1 - (dh_i/drho_i) sum_j m_j dW_ij(h_i)/dh_i = 1 + h_i / (d rho_i) sum_j m_j dW_ij/dh
// (the seed's f_i = 1 / Omega_i) corrects the momentum and energy equations for h's variation.
#include <cstddef>
#include <span>

#include "core/vec.hpp"
#include "particles/cell_grid.hpp"
#include "sph/scaled_kernel.hpp"

namespace partimix::sph {

struct SmoothingLengthSettings {
  double eta = 1.2;         // h = eta (m / rho)^(1/d): h in particle spacings on a lattice
  double tolerance = 1e-8;  // |dh| / h at which a particle's iteration stops
  int max_iterations = 30;
};

struct SmoothingLengthFields {
  std::span<const Vec3> position;
  std::span<const double> mass;
  std::span<double> h;        // in: the guess (the last step's); out: the solution
  std::span<double> density;  // out: the summation density at h
  std::span<double> omega;    // out: Omega
};

struct SmoothingLengthSolve {
  int iterations = 0;      // the most any particle took
  std::size_t failed = 0;  // particles not converged, or whose h outgrew the grid's radius
};

// Solves h, rho and Omega of particles [0, count) with neighbours in [0, count) of `grid`,
// whose radius bounds the support: a particle whose h would exceed grid.radius() / support
// stops there and counts as failed (the caller rebuilds the grid wider and solves again).
SmoothingLengthSolve solve_smoothing_lengths(const SmoothingLengthSettings& settings,
                                             const SmoothingLengthFields& fields, std::size_t count,
                                             const CellGrid& grid, const ScaledKernel& kernel,
                                             int dimensions);

}  // namespace partimix::sph
