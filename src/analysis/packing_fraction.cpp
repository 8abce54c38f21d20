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

// The solid volume (area when flat) of the material particles whose centre lies in the box:
// each particle's `volume` when the particles carry it (superquadric grains), else the ball (in
// 2D the disc) of its `radius`.
double PackingFraction::solid_in_box(const ParticleStore& particles) const {
  const Field<double>* volume = flat_ ? nullptr : particles.find_scalar("volume");
  const Field<double>* radius = particles.find_scalar("radius");
  if (radius == nullptr && volume == nullptr) {
    throw RunError(
        "the analysis packing_fraction needs the particle field 'radius' (DEM grains); these "
        "particles have none");
  }
  double volumes = 0.0;
  double balls = 0.0;  // sum of (4/3) R^3 (R^2 when flat), times pi at the end
  for (std::size_t i = 0; i < particles.size(); ++i) {
    const Vec3& x = particles.position()[i];
    const bool inside =
        (x.array() >= box_.lo.array()).all() && (x.array() <= box_.hi.array()).all();
    if (!particles.is_material(i) || !inside)
      continue;
    if (volume != nullptr) {
      volumes += volume->values[i];
      continue;
    }
    const double r = radius->values[i];
    balls += flat_ ? r * r : r * r * r * (4.0 / 3.0);
  }
  return std::numbers::pi * balls + volumes;
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
