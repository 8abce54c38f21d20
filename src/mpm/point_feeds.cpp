#include "mpm/point_feeds.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "core/error.hpp"
#include "geometry/lattice.hpp"

namespace partimix::mpm {

PointFeeds::PointFeeds(const std::vector<PointFeed>& feeds,
                       const std::vector<materials::GranularMaterial>& materials,
                       const Domain& domain, const io::SizeLimits& limits)
    : dimensions_(domain.dimensions), materials_(materials) {
  geometry::LatticeOptions options;
  options.visits = limits.lattice_points;
  options.points = limits.particles;
  for (std::size_t i = 0; i < feeds.size(); ++i) {
    Cells cells;
    cells.feed = &feeds[i];
    const double s = feeds[i].spacing;
    cells.centres = geometry::fill(*feeds[i].region, s, domain, options);
    if (cells.centres.empty()) {
      throw InputError({"", 0, 0, fmt::format("mpm.feeds[{}].region", i)},
                       fmt::format("the region holds no lattice point of spacing {:.6g} m", s));
    }
    cells.volume = std::pow(s, dimensions_);
    cells.mass = materials_[feeds[i].material].density * cells.volume;
    Vec3 lo = cells.centres.front();
    Vec3 hi = lo;
    for (const Vec3& c : cells.centres) {
      lo = lo.cwiseMin(c);
      hi = hi.cwiseMax(c);
    }
    cells.lo = lo - 0.5 * s * Vec3::Ones();
    for (int axis = 0; axis < dimensions_; ++axis)
      cells.counts[axis] = static_cast<int>(std::lround((hi[axis] - lo[axis]) / s)) + 1;
    cells.occupied.assign(
        static_cast<std::size_t>(cells.counts[0]) * cells.counts[1] * cells.counts[2], 0);
    for (const Vec3& c : cells.centres)
      cells.cell_of.push_back(static_cast<std::size_t>(cell_index(cells, c)));
    cells_.push_back(std::move(cells));
  }
}

// The cell of the feed's box that holds x; -1 outside the box.
std::ptrdiff_t PointFeeds::cell_index(const Cells& cells, const Vec3& x) const {
  std::ptrdiff_t index = 0;
  for (int axis = dimensions_ - 1; axis >= 0; --axis) {
    const double u = std::floor((x[axis] - cells.lo[axis]) / cells.feed->spacing);
    if (!(u >= 0.0 && u < cells.counts[axis]))
      return -1;
    index = index * cells.counts[axis] + static_cast<std::ptrdiff_t>(u);
  }
  return index;
}

double PointFeeds::refill(ParticleStore& store, PointFields& fields, std::int64_t& next_id) {
  double mass = 0.0;
  for (Cells& cells : cells_)
    mass += refill_one(cells, store, fields, next_id);
  return mass;
}

double PointFeeds::refill_one(Cells& cells, ParticleStore& store, PointFields& fields,
                              std::int64_t& next_id) {
  std::fill(cells.occupied.begin(), cells.occupied.end(), 0);
  const PointFeed& feed = *cells.feed;
  double inside = 0.0;
  for (std::size_t p = 0; p < store.size(); ++p) {
    const std::ptrdiff_t cell = cell_index(cells, store.position()[p]);
    if (cell < 0)
      continue;
    cells.occupied[static_cast<std::size_t>(cell)] = 1;
    if (feed.region->signed_distance(store.position()[p]) < 0.0)
      inside += store.mass()[p];
  }
  const double full = cells.mass * static_cast<double>(cells.centres.size());
  double mass = 0.0;
  for (std::size_t k = 0; k < cells.centres.size(); ++k) {
    if (inside + mass > full - 0.5 * cells.mass)
      break;
    if (cells.occupied[cells.cell_of[k]] != 0)
      continue;
    const std::size_t p = store.size();
    store.resize(p + 1);
    store.id()[p] = next_id++;
    store.kind()[p] = static_cast<std::int32_t>(ParticleKind::material_point);
    store.tag()[p] = feed.tag;
    store.position()[p] = cells.centres[k];
    store.velocity()[p] = feed.velocity;
    store.mass()[p] = cells.mass;
    fields.material.values[p] = feed.material;
    fields.volume.values[p] = cells.volume;
    fields.density.values[p] = materials_[feed.material].density;
    mass += cells.mass;
  }
  return mass;
}

}  // namespace partimix::mpm
