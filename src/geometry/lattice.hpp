#pragma once
// Lattice samplers: particles on a Cartesian lattice of a given spacing, filling a shape or
// laying wall layers around it. Lattice points sit at lower + (i + 1/2) spacing, so a filled box
// keeps half a spacing from its faces and the wall surface lies exactly on the shape's surface.
#include <array>
#include <vector>

#include "core/vec.hpp"
#include "geometry/shape.hpp"
#include "particles/domain.hpp"

namespace partimix::geometry {

// A face of a shape's bounding box: axis 0..2, side -1 (lower) or +1 (upper).
struct Face {
  int axis = 0;
  int side = 1;
};

// Points strictly inside the shape (signed distance < 0). Along periodic axes of the domain
// the lattice spans the whole period.
std::vector<Vec3> fill(const Shape& shape, double spacing, const Domain& domain);

// Points outside the shape within `layers` spacings of its surface, except beyond the open
// faces and along the periodic axes of the domain (which carry no wall).
std::vector<Vec3> wall_layers(const Shape& shape, double spacing, int layers,
                              const std::vector<Face>& open_faces, const Domain& domain);

// The layers of a solid body (an impeller): points inside the shape within `layers` spacings of
// its surface (signed distance in (-layers spacing, 0]), on the lattice of fill(). Unlike a
// container, a body is not extended along periodic axes: it is the shape as given.
std::vector<Vec3> inside_layers(const Shape& shape, double spacing, int layers,
                                const Domain& domain);

}  // namespace partimix::geometry
