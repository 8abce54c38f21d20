#include "dem/grain_glyphs.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "dem/glyph_tensors.hpp"

namespace partimix::dem {
namespace {

template <class Field>
const Field& required(const Field* field, const char* name) {
  if (field == nullptr)
    throw std::logic_error(std::string("grain glyphs need the field ") + name);
  return *field;
}

// Writes the 3 x 3 matrix column by column (VTK's order) at `out`.
void put_tensor(const Mat3& tensor, double* out) {
  std::copy(tensor.data(), tensor.data() + 9, out);
}

}  // namespace

GrainGlyphs::GrainGlyphs(std::size_t grains)
    : orientation_(4 * grains),
      blockiness_(2 * grains),
      shape_tensor_(9 * grains),
      superquadric_axes_(9 * grains) {}

std::vector<FrameArray> GrainGlyphs::update(const ParticleStore& grains,
                                            const std::vector<const Superquadric*>& shapes) {
  const auto& w = required(grains.find_scalar("orientation_w"), "orientation_w").values;
  const auto& v = required(grains.find_vector("orientation_v"), "orientation_v").values;
  const auto& axes = required(grains.find_vector("half_axes"), "half_axes").values;
  const auto& species = required(grains.find_integer("species"), "species").values;
  if (orientation_.size() != 4 * grains.size())
    throw std::logic_error("grain glyphs sized for another number of grains");
  for (std::size_t i = 0; i < grains.size(); ++i) {
    const Quaternion q(w[i], v[i].x(), v[i].y(), v[i].z());
    const Superquadric* shape = shapes[static_cast<std::size_t>(species[i])];
    const double quaternion[4] = {q.w(), q.x(), q.y(), q.z()};
    std::copy_n(quaternion, 4, &orientation_[4 * i]);
    blockiness_[2 * i] = shape ? shape->n1() : 2.0;
    blockiness_[2 * i + 1] = shape ? shape->n2() : 2.0;
    put_tensor(shape_tensor(q, axes[i]), &shape_tensor_[9 * i]);
    put_tensor(superquadric_glyph_axes(q, axes[i]), &superquadric_axes_[9 * i]);
  }
  return {{"orientation", 4, orientation_},
          {"blockiness", 2, blockiness_},
          {"shape_tensor", 9, shape_tensor_},
          {"superquadric_axes", 9, superquadric_axes_}};
}

}  // namespace partimix::dem
