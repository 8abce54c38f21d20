#pragma once
// Feeds keep their regions full of material points from the top (docs/mpm.md, "Exits and
// feeds"): the region's lattice is cut into columns along gravity; each column gets points on
// its lattice from its top down to a spacing above the column's highest point.
// Points enter only where the material has left room, so the feed never packs the material
// beyond its lattice density.
#include <cstdint>
#include <vector>

#include "io/size_limits.hpp"
#include "mpm/config.hpp"
#include "mpm/point_fields.hpp"
#include "particles/domain.hpp"
#include "particles/particle_store.hpp"

namespace partimix::mpm {

class PointFeeds {
 public:
  // `gravity` gives "up" (minus its largest component's axis). Throws InputError at
  // "mpm.feeds[i]..." when a region holds no lattice point, or at "gravity" when there is none.
  PointFeeds(const std::vector<PointFeed>& feeds,
             const std::vector<materials::GranularMaterial>& materials, const Domain& domain,
             const Vec3& gravity, const io::SizeLimits& limits);

  // Adds the points the columns have room for; returns the mass added. New points take ids
  // from `next_id` on.
  double refill(ParticleStore& store, PointFields& fields, std::int64_t& next_id);

 private:
  struct Columns {
    const PointFeed* feed = nullptr;
    double mass = 0.0;  // of one point
    double volume = 0.0;
    Vec3 lo = Vec3::Zero();              // of the lattice's box, half a spacing out
    std::array<int, 3> counts{1, 1, 1};  // cells of the box per axis (1 along up)
    double bottom = 0.0;                 // the box's lowest up-coordinate
    std::vector<Vec3> tops;              // each column's top lattice point
    std::vector<double> highest;         // per column: the highest point's up-coordinate
  };
  std::ptrdiff_t column_of(const Columns& columns, const Vec3& x) const;
  double refill_one(Columns& columns, ParticleStore& store, PointFields& fields,
                    std::int64_t& next_id);
  void add_point(const Columns& columns, const Vec3& x, ParticleStore& store, PointFields& fields,
                 std::int64_t& next_id) const;

  int dimensions_;
  int up_ = 1;
  double up_sign_ = 1.0;
  std::vector<materials::GranularMaterial> materials_;
  std::vector<Columns> columns_;
};

}  // namespace partimix::mpm
