#include "mpm/transfers.hpp"

#include <cmath>

namespace partimix::mpm {
namespace {

using grid::NodeWeight;

std::ptrdiff_t signed_size(std::size_t n) {
  return static_cast<std::ptrdiff_t>(n);
}

}  // namespace

void points_to_grid(const grid::CartesianGrid& grid, const grid::NodeBuckets& buckets,
                    const PointView& points, const Vec3& gravity, double min_mass,
                    GridFields& nodes) {
  const std::vector<std::size_t>& active = buckets.active_nodes();
  const double h = grid.cell_size();
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t k = 0; k < signed_size(active.size()); ++k) {
    const std::size_t n = active[k];
    double mass = 0.0;
    Vec3 momentum = Vec3::Zero();
    Vec3 force = Vec3::Zero();
    buckets.for_each_point(grid, n, [&](std::uint32_t p, int a, int b, int c) {
      const NodeWeight w = grid::node_weight(points.stencils[p], a, b, c, h);
      const double m = w.weight * points.mass[p];
      mass += m;
      momentum += m * (points.velocity[p] + points.affine[p] * w.offset);
      force -= points.stress_volume[p] * w.gradient;
    });
    nodes.mass[n] = mass;
    nodes.momentum[n] = momentum;
    nodes.force[n] = force + mass * gravity;
    nodes.velocity[n] = mass > min_mass ? Vec3(momentum / mass) : Vec3::Zero();
  }
}

void momentum_to_grid(const grid::CartesianGrid& grid, const grid::NodeBuckets& buckets,
                      const PointView& points, double min_mass, GridFields& nodes) {
  const std::vector<std::size_t>& active = buckets.active_nodes();
  const double h = grid.cell_size();
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t k = 0; k < signed_size(active.size()); ++k) {
    const std::size_t n = active[k];
    Vec3 momentum = Vec3::Zero();
    buckets.for_each_point(grid, n, [&](std::uint32_t p, int a, int b, int c) {
      const NodeWeight w = grid::node_weight(points.stencils[p], a, b, c, h);
      momentum += w.weight * points.mass[p] * (points.velocity[p] + points.affine[p] * w.offset);
    });
    const double mass = nodes.mass[n];
    nodes.velocity_new[n] = mass > min_mass ? Vec3(momentum / mass) : Vec3::Zero();
  }
}

void advance_nodes(const grid::NodeBuckets& buckets, double dt, double min_mass,
                   GridFields& nodes) {
  const std::vector<std::size_t>& active = buckets.active_nodes();
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t k = 0; k < signed_size(active.size()); ++k) {
    const std::size_t n = active[k];
    const double mass = nodes.mass[n];
    nodes.velocity_new[n] =
        mass > min_mass ? Vec3(nodes.velocity[n] + dt * nodes.force[n] / mass) : Vec3::Zero();
  }
}

// One point's grid velocity, the change of the nodal velocities at the point (FLIP's increment)
// and, with APIC, its affine velocity: the constant-inertia form (quadratic B-splines) or the
// gradient form.
template <bool kApic, bool kConstantInertia>
void gather_point(const grid::CartesianGrid& grid, const grid::PointStencil& stencil,
                  const GridFields& nodes, double inverse_inertia, Vec3& v_grid, Vec3& change,
                  Mat3& affine) {
  grid::for_each_node(grid, stencil, [&](std::size_t n, const NodeWeight& w) {
    const Vec3& v = nodes.velocity_new[n];
    v_grid += w.weight * v;
    change += w.weight * (v - nodes.velocity[n]);
    if constexpr (kApic && kConstantInertia)
      affine.noalias() += (w.weight * inverse_inertia) * v * w.offset.transpose();
    else if constexpr (kApic)
      affine.noalias() += v * w.gradient.transpose();
  });
}

template <bool kApic, bool kConstantInertia>
void grid_to_points_with(const grid::CartesianGrid& grid,
                         std::span<const grid::PointStencil> stencils, const GridFields& nodes,
                         const TransferOptions& options, double kept, std::span<Vec3> velocity,
                         std::span<Mat3> affine, std::span<Vec3> grid_velocity) {
  const double h = grid.cell_size();
  const double inverse_inertia = kConstantInertia ? 1.0 / (options.apic_inertia * h * h) : 0.0;
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t p = 0; p < signed_size(stencils.size()); ++p) {
    Vec3 v_grid = Vec3::Zero();
    Vec3 change = Vec3::Zero();
    Mat3 c = Mat3::Zero();
    gather_point<kApic, kConstantInertia>(grid, stencils[p], nodes, inverse_inertia, v_grid, change,
                                          c);
    grid_velocity[p] = v_grid;
    velocity[p] = kept * (velocity[p] + change) + (1.0 - kept) * v_grid;
    if constexpr (kApic)
      affine[p] = c;
  }
}

void grid_to_points(const grid::CartesianGrid& grid, std::span<const grid::PointStencil> stencils,
                    const GridFields& nodes, const TransferOptions& options, double dt,
                    std::span<Vec3> velocity, std::span<Mat3> affine,
                    std::span<Vec3> grid_velocity) {
  const double kept = options.filter_time > 0.0 ? std::exp(-dt / options.filter_time) : 0.0;
  if (!options.apic)
    grid_to_points_with<false, false>(grid, stencils, nodes, options, kept, velocity, affine,
                                      grid_velocity);
  else if (options.apic_inertia > 0.0)
    grid_to_points_with<true, true>(grid, stencils, nodes, options, kept, velocity, affine,
                                    grid_velocity);
  else
    grid_to_points_with<true, false>(grid, stencils, nodes, options, kept, velocity, affine,
                                     grid_velocity);
}

void velocity_gradients(const grid::CartesianGrid& grid,
                        std::span<const grid::PointStencil> stencils,
                        const std::vector<Vec3>& nodal, std::span<Mat3> gradient) {
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t p = 0; p < signed_size(stencils.size()); ++p) {
    Mat3 l = Mat3::Zero();
    grid::for_each_node(grid, stencils[p], [&](std::size_t n, const NodeWeight& w) {
      l += nodal[n] * w.gradient.transpose();
    });
    gradient[p] = l;
  }
}

void average_dilation(const grid::CartesianGrid& grid, const grid::NodeBuckets& buckets,
                      std::span<const grid::PointStencil> stencils, std::span<const double> mass,
                      double min_mass, GridFields& nodes, std::span<Mat3> gradient) {
  const std::vector<std::size_t>& active = buckets.active_nodes();
  const double h = grid.cell_size();
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t k = 0; k < signed_size(active.size()); ++k) {
    const std::size_t n = active[k];
    double sum = 0.0;
    buckets.for_each_point(grid, n, [&](std::uint32_t p, int a, int b, int c) {
      sum += grid::node_weight(stencils[p], a, b, c, h).weight * mass[p] * gradient[p].trace();
    });
    nodes.dilation[n] = nodes.mass[n] > min_mass ? sum / nodes.mass[n] : 0.0;
  }
  const int dims = grid.dimensions();
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t p = 0; p < signed_size(stencils.size()); ++p) {
    double mean = 0.0;
    grid::for_each_node(grid, stencils[p], [&](std::size_t n, const NodeWeight& w) {
      mean += w.weight * nodes.dilation[n];
    });
    const double shift = (mean - gradient[p].trace()) / dims;
    for (int d = 0; d < dims; ++d)
      gradient[p](d, d) += shift;
  }
}

}  // namespace partimix::mpm
