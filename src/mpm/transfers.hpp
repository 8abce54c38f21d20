#pragma once
// The transfers between material points and grid nodes of one MPM step (docs/mpm.md,
// "Balance laws", "Transfers"). Points-to-grid are gathers over each node's buckets
// (grid/node_buckets.hpp); grid-to-points are loops over the points. Each writes only what it
// owns, so the results do not depend on the thread count.
#include <span>
#include <vector>

#include "core/vec.hpp"
#include "grid/cartesian_grid.hpp"
#include "grid/node_buckets.hpp"
#include "grid/point_stencil.hpp"
#include "mpm/grid_fields.hpp"

namespace partimix::mpm {

// The points as the transfers read them, one entry per point.
struct PointView {
  std::span<const grid::PointStencil> stencils;
  std::span<const double> mass;
  std::span<const Vec3> velocity;
  std::span<const Mat3> affine;         // C_p (zero with FLIP)
  std::span<const Mat3> stress_volume;  // V_p sigma_p
};

// Mass, momentum (with APIC's affine part) and force (internal and gravity) on every active
// node, then the velocity momentum / mass (zero below `min_mass`).
void points_to_grid(const grid::CartesianGrid& grid, const grid::NodeBuckets& buckets,
                    const PointView& points, const Vec3& gravity, double min_mass,
                    GridFields& nodes);

// Momentum only, into nodes.velocity_new as velocity (the MUSL re-map), same masses.
void momentum_to_grid(const grid::CartesianGrid& grid, const grid::NodeBuckets& buckets,
                      const PointView& points, double min_mass, GridFields& nodes);

// v_new = v + dt f / m on every active node with mass.
void advance_nodes(const grid::NodeBuckets& buckets, double dt, double min_mass, GridFields& nodes);

// What grid-to-point gives a point: its velocity on the grid (positions move with it), the
// velocity v_p = k (v_p + sum_i w_ip (v_i^new - v_i)) + (1 - k) sum_i w_ip v_i^new with
// k = exp(-dt / tau) (docs/mpm.md, "Transfers": the filter as a rate) and, with APIC, the
// affine velocity.
struct TransferOptions {
  bool apic = true;
  double filter_time = 0.0;   // tau [s]; 0: k = 0, the filter every step
  double apic_inertia = 0.0;  // D_p / h^2 when constant, else 0: the gradient form
};

// Sets velocity, affine and grid_velocity of every point from nodes.velocity_new and
// nodes.velocity, for a step of dt.
void grid_to_points(const grid::CartesianGrid& grid, std::span<const grid::PointStencil> stencils,
                    const GridFields& nodes, const TransferOptions& options, double dt,
                    std::span<Vec3> velocity, std::span<Mat3> affine,
                    std::span<Vec3> grid_velocity);

// L_p = sum_i v_i grad w_ip^T from the nodal velocities `nodal`.
void velocity_gradients(const grid::CartesianGrid& grid,
                        std::span<const grid::PointStencil> stencils,
                        const std::vector<Vec3>& nodal, std::span<Mat3> gradient);

// The averaged dilation (docs/mpm.md, "Dilation: local or averaged"): the nodes' mass-weighted mean
// of the points' tr L, theta_i = sum_p w_ip m_p tr L_p / m_i, interpolated back to each point,
// theta_p = sum_i w_ip theta_i, replaces tr L_p: L_p += (theta_p - tr L_p) / dims on the
// diagonal of the grid's axes. The deviatoric part of L_p is unchanged.
void average_dilation(const grid::CartesianGrid& grid, const grid::NodeBuckets& buckets,
                      std::span<const grid::PointStencil> stencils, std::span<const double> mass,
                      double min_mass, GridFields& nodes, std::span<Mat3> gradient);

}  // namespace partimix::mpm
