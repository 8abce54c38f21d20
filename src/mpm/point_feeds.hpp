#pragma once
// Feeds keep their regions full of material points (docs/mpm.md, "Exits and feeds"): the
// region's lattice cells are found once; every step a cell that holds no point gets a new one at
// its centre.
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
  // Throws InputError at "mpm.feeds[i]..." when a region holds no lattice point.
  PointFeeds(const std::vector<PointFeed>& feeds,
             const std::vector<materials::GranularMaterial>& materials, const Domain& domain,
             const io::SizeLimits& limits);

  // Adds a point to every empty cell of every feed; returns the mass added. New points take ids
  // from `next_id` on.
  double refill(ParticleStore& store, PointFields& fields, std::int64_t& next_id);

 private:
  struct Cells {
    const PointFeed* feed = nullptr;
    double mass = 0.0;  // of one point
    double volume = 0.0;
    Vec3 lo = Vec3::Zero();              // of the lattice's box, half a spacing out
    std::array<int, 3> counts{1, 1, 1};  // cells of the box per axis
    std::vector<Vec3> centres;           // the region's lattice points
    std::vector<std::size_t> cell_of;    // their cells in the box
    std::vector<std::uint8_t> occupied;  // per cell of the box, this step
  };
  std::ptrdiff_t cell_index(const Cells& cells, const Vec3& x) const;
  double refill_one(Cells& cells, ParticleStore& store, PointFields& fields, std::int64_t& next_id);

  int dimensions_;
  std::vector<materials::GranularMaterial> materials_;
  std::vector<Cells> cells_;
};

}  // namespace partimix::mpm
