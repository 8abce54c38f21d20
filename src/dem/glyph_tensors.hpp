#pragma once
// The tensors from which ParaView's Tensor Glyph filter draws a grain of half-axes (a, b, c)
// turned by Q (body to world) as its own shape (docs/dem.md, "Drawing superquadric grains in
// ParaView"). Both are written column by column (VTK's order of a 3 x 3 tensor).
#include "core/vec.hpp"
#include "dem/rigid_rotation.hpp"

namespace partimix::dem {

// S = Q diag(a, b, c) Q^T: symmetric, eigenvalues a, b, c, eigenvectors the body axes in the
// world frame. The glyph maps a unit sphere onto the grain's ellipsoid, with the eigenvalues
// extracted or not.
Mat3 shape_tensor(const Quaternion& orientation, const Vec3& half_axes);

// M = [a Q e_x, c Q e_z, -b Q e_y]: where the glyph, eigenvalues not extracted, sends the x, y and
// z axes of ParaView's superquadric source, whose symmetry (phi-roundness) axis is y; the source
// of size 1 becomes the grain, blocky or not. det M = a b c (a rotation, not a reflection).
Mat3 superquadric_glyph_axes(const Quaternion& orientation, const Vec3& half_axes);

}  // namespace partimix::dem
