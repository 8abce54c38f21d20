#pragma once
// Surface tension between a phase and the rest as a continuum surface force (Brackbill, Kothe
// & Zemach 1992) in the multi-phase SPH form of Adami, Hu & Adams (2010, J. Comput. Phys. 229,
// 5011), with two changes to their curvature (docs/multi-material-sph.md, "Surface tension").
// With c_i = 1 on the phase and 0 off it and V = m / rho:
// - the colour gradient  grad C_i = 1 / V_i sum_j (V_i^2 + V_j^2) c_ij grad_i W_ij, with
//   c_ij = (rho_j c_i + rho_i c_j) / (rho_i + rho_j) for the force (Adami's density weighting,
//   which puts the force on the denser phase) and (c_i + c_j) / 2 for the normals n_i;
// - the curvature kappa_i = -div n_i, normalised by the divergence of the position in the
//   tangent plane, which a normal field's divergence lives in, with the neighbours that have a
//   normal (|grad C| h above a threshold):
//   kappa_i = -(d - 1) sum_j (n_j - n_i) . grad_i W_ij V_j / sum_j (x_j - x_i) . P_i grad_i W_ij
//   V_j, P_i = I - n_i n_i^T; then smoothed over those neighbours with weights |grad C_j| W_ij V_j;
// - the force per unit mass  a_i = sigma kappa_i grad C_i / rho_i.
// For a droplet of the phase n points inwards and kappa = (d - 1) / R.
#include <cstddef>
#include <cstdint>
#include <span>

#include "core/vec.hpp"
#include "particles/cell_grid.hpp"
#include "sph/kernel_table.hpp"

namespace partimix::sph {

struct InterfaceParticles {
  std::span<const Vec3> position;
  std::span<const double> mass;     // [kg]
  std::span<const double> density;  // [kg/m^3]
  std::span<const double> colour;   // c: 1 on the phase, 0 off it
};

// grad C [1/m] of particles [0, count), with c_ij density-weighted as above or, when not
// `density_weighted`, the plain mean (c_i + c_j) / 2.
void compute_colour_gradients(const InterfaceParticles& particles, std::size_t count,
                              const CellGrid& grid, const KernelTable& kernel,
                              bool density_weighted, std::span<Vec3> colour_gradient);

// kappa [1/m] of particles [0, count) whose |grad C| h exceeds `threshold` (0 elsewhere), from
// the normals' colour gradient; only such neighbours enter the sums.
void compute_curvatures(const InterfaceParticles& particles, std::size_t count,
                        const CellGrid& grid, const KernelTable& kernel, int dimensions, double h,
                        double threshold, std::span<const Vec3> colour_gradient,
                        std::span<double> curvature);

// The curvatures' weighted mean over each particle's neighbours that have one (the smoothing
// above), into `smoothed`; 0 where `curvature` is 0.
void smooth_curvatures(const InterfaceParticles& particles, std::size_t count, const CellGrid& grid,
                       const KernelTable& kernel, std::span<const Vec3> colour_gradient,
                       std::span<const double> curvature, std::span<double> smoothed);

// Adds sigma kappa_i grad C_i / rho_i [m/s^2] to the acceleration of particles [0, count).
void add_surface_tension(const InterfaceParticles& particles, std::size_t count, double sigma,
                         std::span<const Vec3> colour_gradient, std::span<const double> curvature,
                         std::span<Vec3> acceleration);

}  // namespace partimix::sph
