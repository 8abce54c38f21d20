#pragma once
// A grid fluid's time step (docs/cfd.md, "One time step", the projection): the explicit
// convection (cfd/convection.hpp), the momentum predictor with implicit viscosity
// (cfd/momentum_predictor.hpp), and the pressure correction (cfd/pressure_projection.hpp). The
// fluid is Newtonian and fills its cells (ε = 1); with ε η constant the viscous term's transpose
// part ∇·(ε η ∇uᵀ) = ε η ∇(∇·u) vanishes with the divergence and is left out; grains (ε < 1, the
// drag) and the non-Newtonian viscosity bring it in (docs/cfd-dem.md).
#include <vector>

#include "cfd/box_sides.hpp"
#include "cfd/convection.hpp"
#include "cfd/flow_mask.hpp"
#include "cfd/momentum_predictor.hpp"
#include "cfd/pressure_projection.hpp"
#include "core/linear_solve.hpp"
#include "core/vec.hpp"
#include "grid/staggered_grid.hpp"

namespace partimix::cfd {

struct FluidSettings {
  double density = 1000.0;  // ρ [kg/m³]
  double viscosity = 1e-3;  // μ [Pa s]
  Vec3 gravity = Vec3::Zero();
  ConvectionScheme convection = ConvectionScheme::tvd;
  double cfl = 0.4;                  // C_cfl
  double max_dt = 1e-2;              // [s]
  double pressure_tolerance = 1e-8;  // relative residual
  double momentum_tolerance = 1e-10;
  int max_iterations = 1000;
};

class FluidSolver {
 public:
  FluidSolver(const grid::StaggeredGrid& grid, const FlowMask& mask, const BoxSides& sides,
              const FluidSettings& settings);

  // min(C_cfl min_f h / |u_f|, max_dt).
  double stable_dt() const;
  // Advances by dt; the pressure solve's outcome (the momentum solves' in momentum_solve()).
  LinearSolve step(double dt);

  const grid::StaggeredGrid& grid() const { return grid_; }
  const FaceArrays& velocity() const { return velocity_; }
  const FlowMask& mask() const { return mask_; }
  const std::vector<double>& pressure() const { return pressure_; }
  const LinearSolve& momentum_solve() const { return momentum_solve_; }
  // φ of the last step's pressure correction per cell, the next solve's first guess.
  const std::vector<double>& last_correction() const { return correction_; }
  // The state a step reads, from a checkpoint: the face velocities, p and the last φ.
  void restore(const FaceArrays& velocity, const std::vector<double>& pressure,
               const std::vector<double>& correction);
  // The mean of the faces on the cell's two sides along each axis.
  Vec3 cell_velocity(int i, int j, int k) const;

 private:
  void set_side_faces();
  void explicit_terms(double dt);

  grid::StaggeredGrid grid_;
  FlowMask mask_;
  BoxSides sides_;
  FluidSettings settings_;
  FaceArrays velocity_;
  std::vector<double> pressure_;
  std::vector<double> cell_void_fraction_;
  std::vector<double> cell_viscosity_;
  FaceArrays void_fraction_;
  FaceArrays convection_;
  FaceArrays diagonal_;
  FaceArrays rhs_;
  FaceArrays coefficient_;
  std::vector<double> source_;
  std::vector<double> correction_;
  MomentumPredictor predictor_;
  PressureProjection projection_;
  LinearSolve momentum_solve_;
};

}  // namespace partimix::cfd
