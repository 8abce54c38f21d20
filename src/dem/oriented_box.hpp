#pragma once
// An oriented box and the separating-axis test between two of them (Gottschalk, Lin & Manocha
// 1996, "OBBTree"): the boxes are disjoint if and only if their projections are disjoint on one
// of 15 axes, the 3 + 3 face normals and the 9 cross products of an edge of each. The broad
// phase of superquadric contact (docs/dem.md, "Superquadric grains"): a grain lies in the box
// of its half-axes.
#include "core/vec.hpp"

namespace partimix::dem {

struct OrientedBox {
  Vec3 centre;
  Mat3 rotation;  // body to world: the columns are the box's axes
  Vec3 half_extents;
};

// False only when a separating axis is found; nearly parallel edges are treated conservatively
// (such a pair may be reported overlapping, never the other way round).
bool boxes_overlap(const OrientedBox& a, const OrientedBox& b);

}  // namespace partimix::dem
