#include "coupling/kernel_weights.hpp"

#include <algorithm>
#include <cmath>

namespace partimix::coupling {
namespace {

// The range of cell coordinates along `axis` whose centres may lie within `radius` of x; on a
// periodic axis unwrapped, at most one period long.
void cell_range(const grid::StaggeredGrid& grid, int axis, double x, double radius, int& lo,
                int& hi) {
  const double h = grid.spacing(axis);
  const double from = (x - radius - grid.origin()[axis]) / h - 0.5;
  const double to = (x + radius - grid.origin()[axis]) / h - 0.5;
  const int n = grid.cells(axis);
  lo = static_cast<int>(std::ceil(std::max(from, -1.0 * n - 1.0)));
  hi = static_cast<int>(std::floor(std::min(to, 2.0 * n)));
  if (grid.periodic(axis)) {
    if (hi - lo + 1 > n)
      hi = lo + n - 1;
  } else {
    lo = std::max(lo, 0);
    hi = std::min(hi, n - 1);
  }
}

// x_c - x along `axis` through the nearest periodic image.
double separation(const grid::StaggeredGrid& grid, int axis, double centre, double x) {
  double d = centre - x;
  if (grid.periodic(axis)) {
    const double length = grid.cells(axis) * grid.spacing(axis);
    d -= length * std::round(d / length);
  }
  return d;
}

}  // namespace

void KernelWeights::build(const grid::StaggeredGrid& grid, const cfd::FlowMask& mask,
                          std::span<const Vec3> positions, double radius) {
  start_.resize(positions.size() + 1);
  start_[0] = 0;
  weights_.clear();
  unmapped_ = 0;
  for (std::size_t i = 0; i < positions.size(); ++i) {
    add_grain(grid, mask, positions[i], radius);
    start_[i + 1] = weights_.size();
  }
}

void KernelWeights::add_grain(const grid::StaggeredGrid& grid, const cfd::FlowMask& mask,
                              const Vec3& x, double radius) {
  if (!x.allFinite()) {
    ++unmapped_;
    return;
  }
  std::array<int, 3> lo{0, 0, 0};
  std::array<int, 3> hi{0, 0, 0};
  for (int axis = 0; axis < grid.dimensions(); ++axis)
    cell_range(grid, axis, x[axis], radius, lo[axis], hi[axis]);
  const std::size_t first = weights_.size();
  double sum = 0.0;
  for (int k = lo[2]; k <= hi[2]; ++k)
    for (int j = lo[1]; j <= hi[1]; ++j)
      for (int i = lo[0]; i <= hi[0]; ++i) {
        const std::array<int, 3> c{grid.wrap_cell(0, i), grid.wrap_cell(1, j),
                                   grid.wrap_cell(2, k)};
        const std::size_t cell = grid.cell(c[0], c[1], c[2]);
        if (!mask.open_cell[cell])
          continue;
        const Vec3 centre = grid.cell_centre(c[0], c[1], c[2]);
        double r2 = 0.0;
        for (int axis = 0; axis < grid.dimensions(); ++axis) {
          const double d = separation(grid, axis, centre[axis], x[axis]);
          r2 += d * d;
        }
        const double w = wendland_c2(std::sqrt(r2) / radius);
        if (w > 0.0) {
          weights_.push_back({static_cast<std::uint32_t>(cell), w});
          sum += w;
        }
      }
  if (sum > 0.0) {
    for (std::size_t e = first; e < weights_.size(); ++e)
      weights_[e].weight /= sum;
    return;
  }
  if (!add_holding_cell(grid, mask, x))
    ++unmapped_;
}

std::int64_t KernelWeights::holding_cell(const grid::StaggeredGrid& grid, const cfd::FlowMask& mask,
                                         const Vec3& x) {
  std::array<int, 3> c{0, 0, 0};
  for (int axis = 0; axis < grid.dimensions(); ++axis) {
    const double s = (x[axis] - grid.origin()[axis]) / grid.spacing(axis);
    if (!(std::abs(s) < 1e9))
      return -1;
    c[axis] = grid.wrap_cell(axis, static_cast<int>(std::floor(s)));
    if (c[axis] < 0)
      return -1;
  }
  const std::size_t cell = grid.cell(c[0], c[1], c[2]);
  return mask.open_cell[cell] ? static_cast<std::int64_t>(cell) : -1;
}

bool KernelWeights::add_holding_cell(const grid::StaggeredGrid& grid, const cfd::FlowMask& mask,
                                     const Vec3& x) {
  const std::int64_t cell = holding_cell(grid, mask, x);
  if (cell < 0)
    return false;
  weights_.push_back({static_cast<std::uint32_t>(cell), 1.0});
  return true;
}

void KernelWeights::build_divided(const grid::StaggeredGrid& grid, const cfd::FlowMask& mask,
                                  std::span<const Vec3> positions, std::span<const double> radii) {
  start_.resize(positions.size() + 1);
  start_[0] = 0;
  weights_.clear();
  unmapped_ = 0;
  for (std::size_t i = 0; i < positions.size(); ++i) {
    add_divided(grid, mask, positions[i], radii[i]);
    start_[i + 1] = weights_.size();
  }
}

// The sub-cubes' centres x + r ((2k + 1) / 5 - 1) along each axis (the grain's plane in 2D), each
// inside the sphere adding one share to its holding open cell (one entry per cell).
void KernelWeights::add_divided(const grid::StaggeredGrid& grid, const cfd::FlowMask& mask,
                                const Vec3& x, double radius) {
  constexpr int kCuts = 5;
  const std::size_t first = weights_.size();
  if (!x.allFinite()) {
    ++unmapped_;
    return;
  }
  const int depth = grid.dimensions() == 3 ? kCuts : 1;
  int shares = 0;
  for (int k = 0; k < depth; ++k)
    for (int j = 0; j < kCuts; ++j)
      for (int i = 0; i < kCuts; ++i) {
        const auto offset = [&](int n) { return radius * ((2.0 * n + 1.0) / kCuts - 1.0); };
        const Vec3 d(offset(i), offset(j), depth == 1 ? 0.0 : offset(k));
        if (d.squaredNorm() > radius * radius)
          continue;
        const std::int64_t cell = holding_cell(grid, mask, x + d);
        if (cell < 0)
          continue;
        ++shares;
        auto row = std::span(weights_).subspan(first);
        auto found = std::find_if(row.begin(), row.end(), [cell](const Weight& w) {
          return w.cell == static_cast<std::uint32_t>(cell);
        });
        if (found != row.end())
          found->weight += 1.0;
        else
          weights_.push_back({static_cast<std::uint32_t>(cell), 1.0});
      }
  if (shares == 0) {
    ++unmapped_;
    return;
  }
  for (std::size_t e = first; e < weights_.size(); ++e)
    weights_[e].weight /= shares;
}

}  // namespace partimix::coupling
