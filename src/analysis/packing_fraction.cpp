#include "analysis/packing_fraction.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "core/error.hpp"

namespace partimix::analysis {

PackingFraction::PackingFraction(const PackingBox& box)
    : box_(box),
      flat_(box.hi.z() == box.lo.z()),
      measure_(0.0),
      last_(std::numeric_limits<double>::quiet_NaN()) {
  if (!(box.hi.x() > box.lo.x()) || !(box.hi.y() > box.lo.y()) || !(box.hi.z() >= box.lo.z()))
    throw std::invalid_argument("packing_fraction: the box needs max > min along x and y");
  const Vec3 size = box.hi - box.lo;
  measure_ = flat_ ? size.x() * size.y() : size.x() * size.y() * size.z();
}

void PackingFraction::sample(const ParticleStore& particles, double /*time*/,
                             std::span<double> values) {
  const Field<double>* radius = particles.find_scalar("radius");
  if (radius == nullptr) {
    throw RunError(
        "the analysis packing_fraction needs the particle field 'radius' (DEM grains); these "
        "particles have none");
  }
  double solid = 0.0;
  for (std::size_t i = 0; i < particles.size(); ++i) {
    if (!particles.is_material(i))
      continue;
    const Vec3& x = particles.position()[i];
    if ((x.array() >= box_.lo.array()).all() && (x.array() <= box_.hi.array()).all()) {
      const double r = radius->values[i];
      solid += flat_ ? r * r : r * r * r * (4.0 / 3.0);
    }
  }
  last_ = std::numbers::pi * solid / measure_;
  values[0] = last_;
}

void PackingFraction::replay(double /*time*/, std::span<const double> values) {
  last_ = values[0];
}

void PackingFraction::add_figures(Figures& figures) const {
  if (std::isfinite(last_))
    figures.add("packing_fraction_final", last_, "");
}

}  // namespace partimix::analysis
