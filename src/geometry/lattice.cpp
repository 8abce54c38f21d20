#include "geometry/lattice.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "core/error.hpp"

namespace partimix::geometry {
namespace {

// The lattice box: per axis a start point and a count of spacings. Counts are whole numbers
// held as doubles, so that a huge box is measured (and refused) rather than overflowing.
struct LatticeBox {
  std::array<double, 3> start{0.0, 0.0, 0.0};
  std::array<double, 3> count{1.0, 1.0, 1.0};
};

// One axis of the lattice: start + i spacing for i < count.
struct AxisLattice {
  double start = 0.0;
  double count = 0.0;
};

// The number of whole spacings in [from, to], rounded (none when the interval is empty).
double spacings_in(double from, double to, double spacing) {
  return to > from ? std::round((to - from) / spacing) : 0.0;
}

// The points from + (i + 1/2) spacing up to about `to` (half a spacing from each end when the
// length is a whole number of spacings).
AxisLattice counted_up(double from, double to, double spacing) {
  return {from + 0.5 * spacing, spacings_in(from, to, spacing)};
}

// The same lattice counted down from `to`: to - (i + 1/2) spacing down to about `from`.
AxisLattice counted_down(double from, double to, double spacing) {
  const double count = spacings_in(from, to, spacing);
  return {to - (count - 0.5) * spacing, count};
}

// The shape's extent [lo - margin, hi + margin] along one axis, cut at the domain's face where
// the shape has no end there (lattice.hpp): an infinite bound, or a huge one, farther beyond
// the face than the domain's length plus the margin. An uncut extent gives the lattice it
// always had.
AxisLattice axis_lattice(double lo, double hi, double margin, double spacing, double domain_lo,
                         double domain_hi) {
  const double reach = (domain_hi - domain_lo) + margin;
  const bool cut_lo = !(lo >= domain_lo - reach);
  const bool cut_hi = !(hi <= domain_hi + reach);
  if (!cut_lo)
    return counted_up(lo - margin, cut_hi ? domain_hi : hi + margin, spacing);
  if (!cut_hi)
    return counted_down(domain_lo, hi + margin, spacing);
  return counted_up(domain_lo, domain_hi, spacing);
}

LatticeBox lattice_box(const Shape& shape, double spacing, double margin, const Domain& domain) {
  LatticeBox box;
  const Vec3 lo = shape.lower();
  const Vec3 hi = shape.upper();
  for (int axis = 0; axis < domain.dimensions; ++axis) {
    const AxisLattice lattice =
        domain.periodic[axis]
            ? counted_up(domain.lo[axis], domain.hi[axis], spacing)
            : axis_lattice(lo[axis], hi[axis], margin, spacing, domain.lo[axis], domain.hi[axis]);
    box.start[axis] = lattice.start;
    box.count[axis] = lattice.count;
  }
  return box;
}

// The point to measure the shape's distance at: along periodic axes the shape is taken to
// extend without end, so the point is moved onto the shape's middle there (a shape unbounded
// along the axis is left as it is: it has no middle, and no end to remove).
Vec3 probe_point(const Vec3& x, const Shape& shape, const Domain& domain) {
  Vec3 probe = x;
  for (int axis = 0; axis < domain.dimensions; ++axis) {
    const double lo = shape.lower()[axis];
    const double hi = shape.upper()[axis];
    if (domain.periodic[axis] && std::isfinite(lo) && std::isfinite(hi)) {
      probe[axis] = 0.5 * (lo + hi);
    }
  }
  return probe;
}

// Whether `x` lies within the box's extent in x and y (half a spacing beyond its points).
bool within_box_xy(const LatticeBox& box, double spacing, const Vec3& x) {
  for (int axis = 0; axis < 2; ++axis) {
    const double lo = box.start[axis] - 0.5 * spacing;
    const double hi = box.start[axis] + (box.count[axis] - 0.5) * spacing;
    if (x[axis] < lo || x[axis] >= hi)
      return false;
  }
  return true;
}

// The largest distance from `centre` to a corner of the box in x and y.
double reach_xy(const LatticeBox& box, double spacing, const Vec3& centre) {
  double reach = 0.0;
  for (const double x :
       {box.start[0] - 0.5 * spacing, box.start[0] + (box.count[0] - 0.5) * spacing}) {
    for (const double y :
         {box.start[1] - 0.5 * spacing, box.start[1] + (box.count[1] - 0.5) * spacing}) {
      reach = std::max(reach, std::hypot(x - centre.x(), y - centre.y()));
    }
  }
  return reach;
}

// The angle of ring `ring`'s first point [rad]: the golden angle 2 pi (2 - phi) per ring, or
// half a step (of `around` per turn) on the odd rings.
double ring_turn(long ring, long around, bool golden) {
  if (golden)
    return 2.0 * std::numbers::pi * (2.0 - std::numbers::phi) * static_cast<double>(ring);
  return std::numbers::pi / static_cast<double>(around) * static_cast<double>(ring % 2);
}

// Calls visit(x) for each point of the box's Cartesian lattice, or of the rings about
// options.polar_centre within the box; `visits` is how many that will be.
template <class Visit>
void for_each_point(const LatticeBox& box, double spacing, const LatticeOptions& options,
                    Visit&& visit) {
  const auto count = [&box](int axis) { return static_cast<long>(box.count[axis]); };
  for (long k = 0; k < count(2); ++k) {
    const double z = box.start[2] + static_cast<double>(k) * spacing;
    if (!options.polar_centre) {
      for (long j = 0; j < count(1); ++j)
        for (long i = 0; i < count(0); ++i)
          visit(Vec3(box.start[0] + static_cast<double>(i) * spacing,
                     box.start[1] + static_cast<double>(j) * spacing, z));
      continue;
    }
    const Vec3& centre = *options.polar_centre;
    const auto rings = static_cast<long>(std::ceil(reach_xy(box, spacing, centre) / spacing));
    for (long ring = 0; ring < rings; ++ring) {
      const double radius = (static_cast<double>(ring) + 0.5) * spacing;
      const long around = std::max(1L, std::lround(2.0 * std::numbers::pi * radius / spacing));
      const double turn = ring_turn(ring, around, options.golden_rings);
      for (long a = 0; a < around; ++a) {
        const double angle =
            turn + 2.0 * std::numbers::pi * static_cast<double>(a) / static_cast<double>(around);
        const Vec3 x(centre.x() + radius * std::cos(angle), centre.y() + radius * std::sin(angle),
                     z);
        if (within_box_xy(box, spacing, x))
          visit(x);
      }
    }
  }
}

// The points for_each_point visits, about: the box's, or the disc's of the rings.
double visits_of(const LatticeBox& box, double spacing, const LatticeOptions& options) {
  if (!options.polar_centre)
    return box.count[0] * box.count[1] * box.count[2];
  const double rings = std::ceil(reach_xy(box, spacing, *options.polar_centre) / spacing);
  return std::numbers::pi * rings * rings * box.count[2];
}

template <class Keep>
std::vector<Vec3> sample(const LatticeBox& box, double spacing, const LatticeOptions& options,
                         Keep&& keep) {
  const double visits = visits_of(box, spacing, options);
  if (!(visits <= options.visits)) {
    throw InputError({}, fmt::format("at spacing {:.6g} m the lattice spans {:.3g} points, more "
                                     "than limits.lattice_points = {:.3g}",
                                     spacing, visits, options.visits));
  }
  std::vector<Vec3> points;
  for_each_point(box, spacing, options, [&](const Vec3& x) {
    if (!keep(x))
      return;
    if (static_cast<double>(points.size()) >= options.points) {
      throw InputError({}, fmt::format("at spacing {:.6g} m it holds more than "
                                       "limits.particles = {:.3g} particles",
                                       spacing, options.points));
    }
    points.push_back(x);
  });
  return points;
}

}  // namespace

bool fills(const Shape& shape, const Vec3& x, const Domain& domain) {
  return shape.signed_distance(probe_point(x, shape, domain)) < 0.0;
}

std::vector<Vec3> fill(const Shape& shape, double spacing, const Domain& domain,
                       const LatticeOptions& options) {
  const LatticeBox box = lattice_box(shape, spacing, 0.0, domain);
  return sample(box, spacing, options, [&](const Vec3& x) { return fills(shape, x, domain); });
}

std::vector<Vec3> wall_layers(const Shape& shape, double spacing, int layers,
                              const std::vector<Face>& open_faces, const Domain& domain,
                              const LatticeOptions& options) {
  const double thickness = layers * spacing;
  const LatticeBox box = lattice_box(shape, spacing, thickness, domain);
  return sample(box, spacing, options, [&](const Vec3& x) {
    const double distance = shape.signed_distance(probe_point(x, shape, domain));
    return distance > 0.0 && distance < thickness && !shape.beyond_open_end(x, open_faces);
  });
}

std::vector<Vec3> inside_layers(const Shape& shape, double spacing, int layers,
                                const Domain& domain, const LatticeOptions& options) {
  const double thickness = layers * spacing;
  const LatticeBox box = lattice_box(shape, spacing, 0.0, domain);
  return sample(box, spacing, options, [&](const Vec3& x) {
    const double distance = shape.signed_distance(x);
    return distance <= 0.0 && distance > -thickness;
  });
}

}  // namespace partimix::geometry
