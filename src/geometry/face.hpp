#pragma once
// A face of a shape's axis-aligned bounding box. Containers are left open there (the top of a
// vessel): the lattice samplers lay no wall layers beyond an open face (lattice.hpp) and the box
// and cylinder contact surfaces have no face there (box_container_surface.hpp,
// cylinder_vessel_surface.hpp).
namespace partimix::geometry {

// Axis 0..2, side -1 (the lower face) or +1 (the upper face).
struct Face {
  int axis = 0;
  int side = 1;
};

}  // namespace partimix::geometry
