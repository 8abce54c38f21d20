#include "analysis/packing_fraction.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "analysis/grain_volumes.hpp"

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

// The solid volume (area when flat) of the material particles whose centre lies in the box.
double PackingFraction::solid_in_box(const ParticleStore& particles) const {
  const GrainVolumes volume(particles, "packing_fraction", flat_);
  double solid = 0.0;
  for (std::size_t i = 0; i < particles.size(); ++i) {
    const Vec3& x = particles.position()[i];
    const bool inside =
        (x.array() >= box_.lo.array()).all() && (x.array() <= box_.hi.array()).all();
    if (particles.is_material(i) && inside)
      solid += volume(i);
  }
  return solid;
}

void PackingFraction::sample(const ParticleStore& particles, double /*time*/,
                             std::span<double> values) {
  last_ = solid_in_box(particles) / measure_;
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
