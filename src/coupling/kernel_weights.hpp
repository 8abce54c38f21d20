#pragma once
// The weights w_ic by which a grain's volume and force are shared among the open cells of the
// grid fluid (docs/cfd-dem.md, "Void fraction: the grains' volume on the grid"): the Wendland C2
// function W(q) = (1 - q)⁴ (4 q + 1), q = |x_c - x_i| / b (through the nearest periodic image),
// over the open cells whose centres lie within the support radius b, normalised so that each
// grain's weights sum to one. A grain with no open cell within b gives all to the open cell
// that holds its centre; a grain that lies in no open cell (inside a wall, outside the box)
// has no weights and is counted. Or, `divided` (CFDEMcoupling's idea, Goniva et al. 2012): the
// grain's bounding cube cut into 5 x 5 x 5 sub-cubes (5 x 5 in 2D), those whose centres lie in
// the sphere each giving an equal share to the open cell that holds its centre, normalised over
// the shares that found one. Kept in compressed rows (one per grain) whose storage is reused, so
// rebuilding each exchange allocates nothing once sized.
#include <cstdint>
#include <span>
#include <vector>

#include "cfd/flow_mask.hpp"
#include "core/vec.hpp"
#include "grid/staggered_grid.hpp"

namespace partimix::coupling {

class KernelWeights {
 public:
  struct Weight {
    std::uint32_t cell;
    double weight;
  };

  void build(const grid::StaggeredGrid& grid, const cfd::FlowMask& mask,
             std::span<const Vec3> positions, double radius);
  // The divided mapping of grains of radii `radii`.
  void build_divided(const grid::StaggeredGrid& grid, const cfd::FlowMask& mask,
                     std::span<const Vec3> positions, std::span<const double> radii);

  // The weights of grain i.
  std::span<const Weight> of(std::size_t i) const {
    return {weights_.data() + start_[i], start_[i + 1] - start_[i]};
  }
  // Grains that lay in no open cell at the last build.
  std::size_t unmapped() const { return unmapped_; }

 private:
  void add_grain(const grid::StaggeredGrid& grid, const cfd::FlowMask& mask, const Vec3& x,
                 double radius);
  void add_divided(const grid::StaggeredGrid& grid, const cfd::FlowMask& mask, const Vec3& x,
                   double radius);
  // The open cell that holds x, or -1.
  static std::int64_t holding_cell(const grid::StaggeredGrid& grid, const cfd::FlowMask& mask,
                                   const Vec3& x);
  bool add_holding_cell(const grid::StaggeredGrid& grid, const cfd::FlowMask& mask, const Vec3& x);

  std::vector<std::size_t> start_;
  std::vector<Weight> weights_;
  std::size_t unmapped_ = 0;
};

// The Wendland C2 function of q = distance / support, 0 beyond the support.
inline double wendland_c2(double q) {
  if (q >= 1.0)
    return 0.0;
  const double a = 1.0 - q;
  return a * a * a * a * (4.0 * q + 1.0);
}

}  // namespace partimix::coupling
