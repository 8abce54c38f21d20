#include "mpm/point_feeds.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "core/error.hpp"
#include "geometry/lattice.hpp"

namespace partimix::mpm {
namespace {

constexpr double kLowest = -std::numeric_limits<double>::infinity();

}  // namespace

PointFeeds::PointFeeds(const std::vector<PointFeed>& feeds,
                       const std::vector<materials::GranularMaterial>& materials,
                       const Domain& domain, const Vec3& gravity, const io::SizeLimits& limits)
    : dimensions_(domain.dimensions), materials_(materials) {
  if (feeds.empty())
    return;
  if (!(gravity.norm() > 0.0))
    throw InputError({"", 0, 0, "gravity"}, "feeds fill from the top: they need gravity");
  gravity.cwiseAbs().maxCoeff(&up_);
  up_sign_ = gravity[up_] < 0.0 ? 1.0 : -1.0;
  geometry::LatticeOptions options;
  options.visits = limits.lattice_points;
  options.points = limits.particles;
  for (std::size_t i = 0; i < feeds.size(); ++i) {
    Columns columns;
    columns.feed = &feeds[i];
    const double s = feeds[i].spacing;
    const std::vector<Vec3> lattice = geometry::fill(*feeds[i].region, s, domain, options);
    if (lattice.empty()) {
      throw InputError({"", 0, 0, fmt::format("mpm.feeds[{}].region", i)},
                       fmt::format("the region holds no lattice point of spacing {:.6g} m", s));
    }
    columns.volume = std::pow(s, dimensions_);
    columns.mass = materials_[feeds[i].material].density * columns.volume;
    Vec3 lo = lattice.front();
    Vec3 hi = lo;
    for (const Vec3& c : lattice) {
      lo = lo.cwiseMin(c);
      hi = hi.cwiseMax(c);
    }
    columns.lo = lo - 0.5 * s * Vec3::Ones();
    for (int axis = 0; axis < dimensions_; ++axis) {
      if (axis != up_)
        columns.counts[axis] = static_cast<int>(std::lround((hi[axis] - lo[axis]) / s)) + 1;
    }
    columns.bottom = up_sign_ > 0.0 ? lo[up_] - 0.5 * s : -(hi[up_] + 0.5 * s);
    const std::size_t count =
        static_cast<std::size_t>(columns.counts[0]) * columns.counts[1] * columns.counts[2];
    columns.tops.assign(count, Vec3::Constant(std::numeric_limits<double>::quiet_NaN()));
    for (const Vec3& c : lattice) {
      const auto k = static_cast<std::size_t>(column_of(columns, c));
      if (std::isnan(columns.tops[k][up_]) || up_sign_ * c[up_] > up_sign_ * columns.tops[k][up_])
        columns.tops[k] = c;
    }
    columns.highest.assign(count, kLowest);
    columns_.push_back(std::move(columns));
  }
}

// The column of the feed's box that holds x (laterally; at any height); -1 outside it.
std::ptrdiff_t PointFeeds::column_of(const Columns& columns, const Vec3& x) const {
  std::ptrdiff_t index = 0;
  for (int axis = dimensions_ - 1; axis >= 0; --axis) {
    if (axis == up_)
      continue;
    const double u = std::floor((x[axis] - columns.lo[axis]) / columns.feed->spacing);
    if (!(u >= 0.0 && u < columns.counts[axis]))
      return -1;
    index = index * columns.counts[axis] + static_cast<std::ptrdiff_t>(u);
  }
  return index;
}

double PointFeeds::refill(ParticleStore& store, PointFields& fields, std::int64_t& next_id) {
  double mass = 0.0;
  for (Columns& columns : columns_)
    mass += refill_one(columns, store, fields, next_id);
  return mass;
}

void PointFeeds::add_point(const Columns& columns, const Vec3& x, ParticleStore& store,
                           PointFields& fields, std::int64_t& next_id) const {
  const PointFeed& feed = *columns.feed;
  const std::size_t p = store.size();
  store.resize(p + 1);
  store.id()[p] = next_id++;
  store.kind()[p] = static_cast<std::int32_t>(ParticleKind::material_point);
  store.tag()[p] = feed.tag;
  store.position()[p] = x;
  store.velocity()[p] = feed.velocity;
  store.mass()[p] = columns.mass;
  fields.material.values[p] = feed.material;
  fields.volume.values[p] = columns.volume;
  fields.density.values[p] = materials_[feed.material].density;
}

// The highest point above the box's bottom in each column; each column gets points on its
// lattice from the top down to a spacing above that point.
double PointFeeds::refill_one(Columns& columns, ParticleStore& store, PointFields& fields,
                              std::int64_t& next_id) {
  std::fill(columns.highest.begin(), columns.highest.end(), kLowest);
  for (const Vec3& x : store.position()) {
    const double height = up_sign_ * x[up_];
    const std::ptrdiff_t k = column_of(columns, x);
    if (k >= 0 && height >= columns.bottom)
      columns.highest[static_cast<std::size_t>(k)] =
          std::max(columns.highest[static_cast<std::size_t>(k)], height);
  }
  const PointFeed& feed = *columns.feed;
  double mass = 0.0;
  Vec3 step = Vec3::Zero();
  step[up_] = -up_sign_ * feed.spacing;
  for (std::size_t k = 0; k < columns.tops.size(); ++k) {
    if (std::isnan(columns.tops[k][up_]))
      continue;
    // From the top lattice point down, as long as a spacing of room is left above the highest
    // point and the lattice point is within the region.
    for (Vec3 x = columns.tops[k]; up_sign_ * x[up_] >= columns.highest[k] + feed.spacing &&
                                   up_sign_ * x[up_] > columns.bottom;
         x += step) {
      add_point(columns, x, store, fields, next_id);
      mass += columns.mass;
    }
  }
  return mass;
}

}  // namespace partimix::mpm
