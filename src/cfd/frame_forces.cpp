#include "cfd/frame_forces.hpp"

#include "cfd/face_stencil.hpp"

namespace partimix::cfd {
namespace {

// Component b at face f of component a (b ≠ a): the mean of the b-faces of the cells on f's
// two sides.
double across(const grid::StaggeredGrid& grid, const FaceArrays& velocity, int a, int b,
              const Coordinates& f) {
  double sum = 0.0;
  for (const int side : {-1, 1}) {
    Coordinates cell;
    cell_beside(grid, a, f, side, cell);
    Coordinates upper = cell;
    upper[b] = grid.wrap_face(b, cell[b] + 1);
    sum += velocity[b][face_index(grid, b, cell)] + velocity[b][face_index(grid, b, upper)];
  }
  return 0.25 * sum;
}

}  // namespace

void add_frame_forces(const grid::StaggeredGrid& grid, const FlowMask& mask,
                      const FrameForces& forces, const FaceArrays& density,
                      const FaceArrays& void_fraction, const FaceArrays& velocity,
                      FaceArrays& rhs) {
  const Vec3& omega = forces.omega;
  for (int a = 0; a < grid.dimensions(); ++a)
    grid.for_each_face(a, [&](const Coordinates& f, std::size_t index) {
      if (!mask.open_face[a][index])
        return;
      Vec3 u = Vec3::Zero();
      for (int b = 0; b < grid.dimensions(); ++b)
        u[b] = b == a ? velocity[a][index] : across(grid, velocity, a, b, f);
      const Vec3 r = grid.face_centre(a, f[0], f[1], f[2]) - forces.axis_point;
      const Vec3 acceleration =
          -2.0 * omega.cross(u) - omega.cross(omega.cross(r)) - forces.omega_rate.cross(r);
      rhs[a][index] += void_fraction[a][index] * density[a][index] * acceleration[a];
    });
}

}  // namespace partimix::cfd
