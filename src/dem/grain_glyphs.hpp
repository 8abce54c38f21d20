#pragma once
// The arrays of a DEM frame from which ParaView draws every grain as its own shape (docs/dem.md,
// "Drawing superquadric grains in ParaView"), beside the store's `half_axes` field:
//   orientation        4 components, the quaternion (w, x, y, z), body to world;
//   blockiness         2 components, (n1, n2); (2, 2) for a sphere;
//   shape_tensor       9 components, Q diag(a, b, c) Q^T (dem/glyph_tensors.hpp);
//   superquadric_axes  9 components, [a Q e_x, c Q e_z, -b Q e_y] (dem/glyph_tensors.hpp).
// Sized once for the grains; filled only when a frame is written, never in a step.
#include <vector>

#include "dem/superquadric.hpp"
#include "particles/frame_array.hpp"
#include "particles/particle_store.hpp"

namespace partimix::dem {

class GrainGlyphs {
 public:
  explicit GrainGlyphs(std::size_t grains);

  // Fills the arrays from the grains' fields orientation_w, orientation_v, half_axes and species,
  // with `shapes` by species (null: a sphere), and returns them (valid until the next update).
  std::vector<FrameArray> update(const ParticleStore& grains,
                                 const std::vector<const Superquadric*>& shapes);

 private:
  std::vector<double> orientation_;
  std::vector<double> blockiness_;
  std::vector<double> shape_tensor_;
  std::vector<double> superquadric_axes_;
};

}  // namespace partimix::dem
