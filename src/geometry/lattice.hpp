#pragma once
// Lattice samplers: particles on a Cartesian lattice of a given spacing, filling a shape or
// laying wall layers around it. Lattice points sit at lower + (i + 1/2) spacing, so a filled box
// keeps half a spacing from its faces and the wall surface lies exactly on the shape's surface.
//
// Along each axis the lattice spans the shape's bounding box (plus the wall thickness for
// wall_layers), cut at the domain's face where the shape has no end: an infinite bound (a plane,
// a drum), or a huge one (farther beyond the face than the domain's length plus the wall
// thickness). So such shapes give points inside the domain only along those axes. A shape that
// pokes out of the domain by less keeps its whole lattice, and the run reports the points
// outside the domain. Where only one end is cut, the lattice keeps the phase of the other, so
// that the layers behind a plane sit (j + 1/2) spacings from it; where both are, the lattice is
// the domain's: domain.lo + (i + 1/2) spacing.
#include <array>
#include <optional>
#include <vector>

#include "core/vec.hpp"
#include "geometry/face.hpp"
#include "geometry/shape.hpp"
#include "particles/domain.hpp"

namespace partimix::geometry {

// How the points are laid and what a sampler may cost.
// - polar_centre: when given, the points lie on rings about the axis through it parallel to z
//   (in 2D: circles in the plane), ring k at radius (k + 1/2) spacing holding
//   round(2 pi r_k / spacing) points evenly spread from angle 0 (odd rings turned by half a
//   step, so that neighbouring rings interleave); along z the lattice stays
//   Cartesian. A circle about the centre whose radius is a whole number of spacings then lies
//   half a spacing from the rings on both sides, so that curved walls are smooth. Only the
//   points within the Cartesian lattice box (below) are taken.
// - golden_rings: ring k turned by k times the golden angle (137.5 degrees) instead of the odd
//   rings by half a step. Neighbouring rings, whose counts differ by about six, fall into step
//   at six angles; staggered, every pair does so at about the same six, which makes radial seams
//   through a thin layer of rings (a droplet's shell); golden, each pair at its own.
// - visits, points: the lattice points a sampler may visit (the box it spans) and keep. Past
//   either it throws InputError (without a location: the caller knows which key asked) before
//   it allocates, whatever the shape's size: the case's limits (io/size_limits.hpp) come here.
struct LatticeOptions {
  std::optional<Vec3> polar_centre;
  bool golden_rings = false;
  double visits = 1.0e9;
  double points = 1.0e9;
};

// Whether fill() takes the lattice point x of the shape: its signed distance is < 0, probed
// along periodic axes at the shape's middle.
bool fills(const Shape& shape, const Vec3& x, const Domain& domain);

// Points strictly inside the shape (signed distance < 0). Along periodic axes of the domain
// the lattice spans the whole period.
std::vector<Vec3> fill(const Shape& shape, double spacing, const Domain& domain,
                       const LatticeOptions& options = {});

// Points outside the shape within `layers` spacings of its surface, except beyond its open ends
// (Shape::beyond_open_end: by default the open faces of its bounding box) and along the periodic
// axes of the domain (which carry no wall).
std::vector<Vec3> wall_layers(const Shape& shape, double spacing, int layers,
                              const std::vector<Face>& open_faces, const Domain& domain,
                              const LatticeOptions& options = {});

// The layers of a solid body (an impeller): points inside the shape within `layers` spacings of
// its surface (signed distance in (-layers spacing, 0]), on the lattice of fill(). Unlike a
// container, a body is not extended along periodic axes: it is the shape as given.
std::vector<Vec3> inside_layers(const Shape& shape, double spacing, int layers,
                                const Domain& domain, const LatticeOptions& options = {});

}  // namespace partimix::geometry
