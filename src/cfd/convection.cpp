#include "cfd/convection.hpp"

#include "cfd/face_stencil.hpp"

namespace partimix::cfd {
namespace {

// The continuity flux ε u_b [m/s] through the control-volume face of face f of component a on
// side `side` along axis b: the mean of the two faces of component b it lies between.
double advecting_flux(const grid::StaggeredGrid& grid, int a, const Coordinates& f, int b, int side,
                      const FaceArrays& void_fraction, const FaceArrays& velocity) {
  Coordinates first;
  Coordinates second;
  if (b == a) {
    // The control-volume face is the cell beside f: its two faces of component a.
    Coordinates beyond;
    neighbour_face(grid, a, f, a, side, beyond);
    first = f;
    second = beyond;
  } else {
    // The edge between f and its neighbour along b: the b-faces of the cells on f's two sides,
    // at the face number between f's row and the neighbour's.
    cell_beside(grid, a, f, -1, first);
    cell_beside(grid, a, f, 1, second);
    const int number = grid.wrap_face(b, f[b] + (side > 0 ? 1 : 0));
    first[b] = second[b] = number;
  }
  const std::size_t i = face_index(grid, b, first);
  const std::size_t j = face_index(grid, b, second);
  return 0.5 * (void_fraction[b][i] * velocity[b][i] + void_fraction[b][j] * velocity[b][j]);
}

// The advected value at the face between node p and its neighbour n along b on side `side`,
// for a flux `flux` in b's direction.
double advected_value(const grid::StaggeredGrid& grid, ConvectionScheme scheme, int a,
                      const Coordinates& p, const Coordinates& n, int b, int side, double flux,
                      const std::vector<double>& u) {
  const bool p_upwind = (flux >= 0.0) == (side > 0);
  const Coordinates& upwind = p_upwind ? p : n;
  const Coordinates& downwind = p_upwind ? n : p;
  const double phi_u = u[face_index(grid, a, upwind)];
  if (scheme == ConvectionScheme::upwind)
    return phi_u;
  Coordinates far;
  if (!neighbour_face(grid, a, upwind, b, flux >= 0.0 ? -1 : 1, far))
    return phi_u;
  const double phi_d = u[face_index(grid, a, downwind)];
  const double jump = phi_d - phi_u;
  if (jump == 0.0)
    return phi_u;
  const double r = (phi_u - u[face_index(grid, a, far)]) / jump;
  return phi_u + 0.5 * van_leer(r) * jump;
}

// The advected component a on a side of the box that f's control volume reaches: an outlet's
// the face's own (zero gradient across it), a wall's its velocity (what an inlet brings in; a
// wall with no flow across it carries no flux).
double value_on_side(const BoxSide& wall, int a, double own) {
  return wall.outlet ? own : wall.velocity[a];
}

}  // namespace

void convective_term(const grid::StaggeredGrid& grid, const FlowMask& mask, const BoxSides& sides,
                     ConvectionScheme scheme, double density, const FaceArrays& void_fraction,
                     const FaceArrays& velocity, FaceArrays& out) {
  for (int a = 0; a < grid.dimensions(); ++a) {
    out[a].assign(grid.face_count(a), 0.0);
    grid.for_each_face(a, [&](const Coordinates& p, std::size_t f) {
      if (!mask.open_face[a][f])
        return;
      double sum = 0.0;
      for (int b = 0; b < grid.dimensions(); ++b)
        for (const int side : {-1, 1}) {
          Coordinates n;
          const bool inside = neighbour_face(grid, a, p, b, side, n);
          if (!inside && b == a)
            continue;  // f lies on the side itself: not an unknown
          const double flux = advecting_flux(grid, a, p, b, side, void_fraction, velocity);
          const double mass = density * flux * grid.face_area(b);
          const double value =
              inside ? advected_value(grid, scheme, a, p, n, b, side, flux, velocity[a])
                     : value_on_side(box_side(sides, b, side), a, velocity[a][f]);
          sum += side * mass * value;
        }
      out[a][f] = sum / grid.cell_volume();
    });
  }
}

}  // namespace partimix::cfd
