#pragma once
// The implicit part of a grid fluid's momentum predictor (docs/cfd.md, "One time step", step 1):
// for each velocity component a and each of its open faces f,
//
//     D_f u*_f - (1/V) Σ_nb (ε η)_nb A_nb / h_nb (u*_nb - u*_f) = r_f
//
// with D_f = ρ ε_f / Δt + K_f and r_f the explicit terms, given by the caller; the sum runs over
// the faces of f's control volume: along a through the cells on f's two sides (ε η of the cell),
// along each other axis b through the edges f shares with its neighbours (ε η the mean of the
// open cells around the edge). A neighbour face whose velocity is set (a box side, against a
// blocked cell) enters as a known value; where the neighbour lies beyond a no-slip wall
// (outside the box, or between two blocked cells) the ghost value 2 u_wall - u*_f puts u_wall
// on the wall half a cell away; a slip or outlet side adds nothing. Blocked cells' walls are at
// rest unless set_wall_velocities gives them a velocity (a moving wall's, along its surface). Each
// component's system is symmetric positive definite, solved by conjugate gradients; its pattern is
// laid out once per mask, its values refilled each step without allocating.
#include <array>
#include <cstdint>
#include <functional>
#include <utility>
#include <vector>

#include <Eigen/SparseCore>

#include "cfd/box_sides.hpp"
#include "cfd/face_stencil.hpp"
#include "cfd/flow_mask.hpp"
#include "core/conjugate_gradient.hpp"
#include "core/linear_solve.hpp"
#include "core/sparse_pattern.hpp"
#include "core/vec.hpp"
#include "grid/staggered_grid.hpp"

namespace partimix::cfd {

class MomentumPredictor {
 public:
  MomentumPredictor(double tolerance, int max_iterations);

  void lay_out(const grid::StaggeredGrid& grid, const FlowMask& mask);

  // u* on the open faces of `velocity` (the set faces are read, not written). diagonal: D_f and
  // rhs: r_f on the open faces; void_fraction and viscosity: ε and η per cell.
  LinearSolve solve(const grid::StaggeredGrid& grid, const BoxSides& sides,
                    const std::vector<double>& void_fraction, const std::vector<double>& viscosity,
                    const FaceArrays& diagonal, const FaceArrays& rhs, FaceArrays& velocity);
  // The velocity of the walls behind blocked cells, for the ghost values: velocity_at(x, cell) at
  // the staircase point x half a cell from the face, `cell` the blocked cell behind it.
  void set_wall_velocities(const grid::StaggeredGrid& grid,
                           const std::function<Vec3(const Vec3&, std::size_t)>& velocity_at);

 private:
  // How one neighbour of a face enters its row.
  enum class Link : std::uint8_t { unknown, known, box_wall, blocked_wall };
  struct Term {
    std::uint32_t row;
    Link link;
    std::int8_t along;  // the axis of the step to the neighbour
    std::int8_t side;   // -1 or +1
    int diagonal;
    int off_diagonal;                   // unknown: the neighbour's slot
    std::size_t neighbour;              // unknown, known: the neighbour face
    std::array<std::int64_t, 4> cells;  // the cells whose ε η the coefficient averages, -1 none
    std::int64_t wall_cell = -1;        // blocked_wall: the blocked cell behind the wall
    double wall_velocity = 0.0;         // blocked_wall: the wall's velocity along the component
  };
  struct Component {
    Eigen::SparseMatrix<double, Eigen::RowMajor> matrix;
    Eigen::VectorXd rhs, solution;
    std::vector<std::size_t> row_face;
    std::vector<std::int64_t> unknown;  // per face: its row, -1 set
    std::vector<Term> terms;
    std::vector<std::size_t> term_start;
  };

  void lay_out_component(const grid::StaggeredGrid& grid, const FlowMask& mask, int axis);
  void lay_out_row(const grid::StaggeredGrid& grid, const FlowMask& mask, int axis,
                   const Coordinates& f, Component& component);
  Term link_to(const grid::StaggeredGrid& grid, const FlowMask& mask, int axis,
               const Coordinates& f, int along, int side, const Component& component) const;
  void fill(const grid::StaggeredGrid& grid, const BoxSides& sides, int axis,
            const std::vector<double>& void_fraction, const std::vector<double>& viscosity,
            const FaceArrays& diagonal, const FaceArrays& rhs, const FaceArrays& velocity,
            Component& component) const;

  std::array<ConjugateGradient, 3> solvers_;
  std::array<Component, 3> components_;
  SparsePattern pattern_;
  std::vector<std::pair<std::int64_t, int>> entries_;
  std::vector<int> slots_;
};

}  // namespace partimix::cfd
