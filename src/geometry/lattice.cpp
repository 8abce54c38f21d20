#include "geometry/lattice.hpp"

#include <cmath>

namespace partimix::geometry {
namespace {

// The lattice box: per axis a start point and a count of spacings.
struct LatticeBox {
  std::array<double, 3> start{0.0, 0.0, 0.0};
  std::array<long, 3> count{1, 1, 1};
};

LatticeBox lattice_box(const Shape& shape, double spacing, double margin, const Domain& domain) {
  LatticeBox box;
  const Vec3 lo = shape.lower();
  const Vec3 hi = shape.upper();
  for (int axis = 0; axis < domain.dimensions; ++axis) {
    double from = lo[axis] - margin;
    double to = hi[axis] + margin;
    if (domain.periodic[axis]) {
      from = domain.lo[axis];
      to = domain.hi[axis];
    }
    box.start[axis] = from + 0.5 * spacing;
    box.count[axis] = std::max(0L, std::lround((to - from) / spacing));
  }
  return box;
}

// The point to measure the shape's distance at: along periodic axes the shape is taken to
// extend without end, so the point is moved onto the shape's middle there.
Vec3 probe_point(const Vec3& x, const Shape& shape, const Domain& domain) {
  Vec3 probe = x;
  for (int axis = 0; axis < domain.dimensions; ++axis) {
    if (domain.periodic[axis]) {
      probe[axis] = 0.5 * (shape.lower()[axis] + shape.upper()[axis]);
    }
  }
  return probe;
}

template <class Keep>
std::vector<Vec3> sample(const LatticeBox& box, double spacing, Keep&& keep) {
  std::vector<Vec3> points;
  for (long k = 0; k < box.count[2]; ++k) {
    for (long j = 0; j < box.count[1]; ++j) {
      for (long i = 0; i < box.count[0]; ++i) {
        const Vec3 x(box.start[0] + static_cast<double>(i) * spacing,
                     box.start[1] + static_cast<double>(j) * spacing,
                     box.start[2] + static_cast<double>(k) * spacing);
        if (keep(x)) {
          points.push_back(x);
        }
      }
    }
  }
  return points;
}

bool beyond_open_face(const Vec3& x, const Shape& shape, const std::vector<Face>& open_faces) {
  for (const Face& face : open_faces) {
    if (face.side > 0 && x[face.axis] > shape.upper()[face.axis])
      return true;
    if (face.side < 0 && x[face.axis] < shape.lower()[face.axis])
      return true;
  }
  return false;
}

}  // namespace

std::vector<Vec3> fill(const Shape& shape, double spacing, const Domain& domain) {
  const LatticeBox box = lattice_box(shape, spacing, 0.0, domain);
  return sample(box, spacing, [&](const Vec3& x) {
    return shape.signed_distance(probe_point(x, shape, domain)) < 0.0;
  });
}

std::vector<Vec3> wall_layers(const Shape& shape, double spacing, int layers,
                              const std::vector<Face>& open_faces, const Domain& domain) {
  const double thickness = layers * spacing;
  const LatticeBox box = lattice_box(shape, spacing, thickness, domain);
  return sample(box, spacing, [&](const Vec3& x) {
    const double distance = shape.signed_distance(probe_point(x, shape, domain));
    return distance > 0.0 && distance < thickness && !beyond_open_face(x, shape, open_faces);
  });
}

std::vector<Vec3> inside_layers(const Shape& shape, double spacing, int layers,
                                const Domain& domain) {
  const double thickness = layers * spacing;
  const LatticeBox box = lattice_box(shape, spacing, 0.0, domain);
  return sample(box, spacing, [&](const Vec3& x) {
    const double distance = shape.signed_distance(x);
    return distance <= 0.0 && distance > -thickness;
  });
}

}  // namespace partimix::geometry
