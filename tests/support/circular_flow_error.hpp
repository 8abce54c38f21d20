#pragma once
// The grid fluid's open faces against a circular flow about the z axis, u = speed(r) e_θ: the
// root mean square over the faces of the face velocity less the exact one's component at the
// face centre (the Couette tests of tests/cfd/).
#include <array>
#include <cmath>

#include "cfd/fluid_solver.hpp"

namespace partimix::test_support {

template <class Speed>
double circular_flow_rms(const cfd::FluidSolver& fluid, Speed&& speed) {
  const grid::StaggeredGrid& grid = fluid.grid();
  double squares = 0.0;
  double count = 0.0;
  for (int a = 0; a < grid.dimensions(); ++a)
    grid.for_each_face(a, [&](const std::array<int, 3>& f, std::size_t index) {
      if (!fluid.mask().open_face[a][index])
        return;
      const Vec3 x = grid.face_centre(a, f[0], f[1], f[2]);
      const double r = std::hypot(x.x(), x.y());
      const Vec3 exact = speed(r) / r * Vec3(-x.y(), x.x(), 0.0);
      squares += std::pow(fluid.velocity()[a][index] - exact[a], 2);
      count += 1.0;
    });
  return std::sqrt(squares / count);
}

}  // namespace partimix::test_support
