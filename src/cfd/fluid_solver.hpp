#pragma once
// A grid fluid's time step (docs/cfd.md, "One time step", the projection): the explicit
// convection (cfd/convection.hpp), the momentum predictor with implicit viscosity and the grains'
// implicit drag (cfd/momentum_predictor.hpp), and the pressure correction
// (cfd/pressure_projection.hpp), with the void fraction ε of the grains (1 without them) and the
// continuity source (ε^{n+1} - ε^n) / Δt. The viscosity is the shared rheology's (materials/
// rheology.hpp): constant for a Newtonian fluid, else η(γ̇) per cell from the shear rate of the
// last step's velocity (cfd/cell_shear_rate.hpp; docs/cfd.md, "Non-Newtonian viscosity"). The
// viscous term's transpose part ∇·(ε η ∇uᵀ) is explicit (cfd/transpose_viscous.hpp). In a
// rotating frame the gravity turns and the fictitious forces join the explicit terms
// (cfd/frame_forces.hpp); walls moving along their surfaces give the ghost values their velocity.
#include <array>
#include <functional>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "cfd/box_sides.hpp"
#include "cfd/convection.hpp"
#include "cfd/flow_mask.hpp"
#include "cfd/fluid_frame.hpp"
#include "cfd/interface_compression.hpp"
#include "cfd/momentum_predictor.hpp"
#include "cfd/phase_transport.hpp"
#include "cfd/pressure_projection.hpp"
#include "cfd/wall_faces.hpp"
#include "core/linear_solve.hpp"
#include "core/vec.hpp"
#include "grid/staggered_grid.hpp"
#include "materials/rheology.hpp"

namespace partimix::cfd {

// The light phase of a two-phase fluid, above the heavy one (air over mortar; docs/cfd.md, "Two
// phases: volume of fluid"): Newtonian.
struct LightPhase {
  double density = 1.2;       // [kg/m³]
  double viscosity = 1.8e-5;  // [Pa s]
  double compression = 1.0;   // c_α of the interface compression (0: none)
};

struct FluidSettings {
  double density = 1000.0;  // ρ [kg/m³]; of the heavy phase when there are two
  // η(γ̇); by default water's μ = 1e-3 Pa s.
  materials::RheologyConfig rheology = [] {
    materials::RheologyConfig water;
    water.viscosity = 1e-3;
    return water;
  }();
  std::optional<LightPhase> light_phase;  // none: one phase fills the open cells
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

  // min(C_cfl min_f h / |u_f|, max_dt), and with two phases the volume fraction's limit
  // (cfd/phase_transport.hpp).
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
               const std::vector<double>& correction, const std::vector<double>& void_fraction);
  // The grains' void fraction per cell for the next step, ε^{n+1}; the present one becomes ε^n.
  void set_void_fraction(std::span<const double> cells);
  // The same, with no change over the first step (a run's start): ε^n = ε^{n+1}.
  void start_void_fraction(std::span<const double> cells);
  const std::vector<double>& void_fraction() const { return cell_void_fraction_; }
  // ε on the faces: the mean of the cells on the face's two sides (open faces only).
  const FaceArrays& face_void_fraction() const { return void_fraction_; }
  // The grains' drag on the fluid for the next step, S_e - K_f u*, per unit volume on each open
  // face (docs/cfd-dem.md, "The source S_p"): K_f [kg/(m³ s)] and S_e [N/m³], written by the
  // coupling, zero without grains.
  FaceArrays& drag_coefficient() { return drag_coefficient_; }
  FaceArrays& grain_source() { return grain_source_; }
  const FaceArrays& drag_coefficient() const { return drag_coefficient_; }
  const FaceArrays& grain_source() const { return grain_source_; }
  const FluidSettings& settings() const { return settings_; }
  // η per cell [Pa s] at the present velocity, the next step's (the rheology's at the shear rate
  // now; with two phases α η_heavy + (1 - α) η_light).
  const std::vector<double>& viscosity() const { return cell_viscosity_; }
  // ρ per cell [kg/m³]: the settings' density, with two phases α ρ_heavy + (1 - α) ρ_light.
  const std::vector<double>& density() const { return cell_density_; }
  // With two phases the heavy phase's volume fraction α per cell (1 with one phase); the step
  // carries it (cfd/phase_transport.hpp).
  bool two_phases() const { return settings_.light_phase.has_value(); }
  const std::vector<double>& phase_fraction() const { return phase_fraction_; }
  // α per cell, at the start or from a checkpoint (two phases only).
  void set_phase_fraction(std::span<const double> cells);

  // The frame's gravity and fictitious forces for the next step (by default the settings'
  // gravity, no rotation).
  void set_frame_forces(const FrameForces& forces) { frame_forces_ = forces; }
  // The velocity of the walls of blocked cells for the next step, velocity_at(x, blocked cell):
  // the ghost values behind them (cfd/momentum_predictor.hpp), and the faces of blocked cells,
  // which take the wall's velocity at their centre (docs/cfd.md, "Moving walls and the rotating
  // frame").
  void set_wall_velocities(const std::function<Vec3(const Vec3&, std::size_t)>& velocity_at);
  // The velocity before the last step in a rotating frame, u^{n-1}, which the Coriolis term's
  // estimate takes; the start's velocity before the first step and without rotation.
  const FaceArrays& previous_velocity() const { return previous_velocity_; }
  void restore_previous_velocity(const FaceArrays& velocity) { previous_velocity_ = velocity; }

  // The mean of the faces on the cell's two sides along each axis.
  Vec3 cell_velocity(int i, int j, int k) const;

 private:
  void set_side_faces();
  void list_wall_faces();
  void faces_from_cells(const std::vector<double>& cells, FaceArrays& faces) const;
  void explicit_terms(double dt);
  void extrapolate_to_outlets();
  void update_viscosity();
  void update_density();

  grid::StaggeredGrid grid_;
  FlowMask mask_;
  BoxSides sides_;
  FluidSettings settings_;
  FaceArrays velocity_;
  WallFaces wall_faces_;
  FaceArrays previous_velocity_;  // u^{n-1}
  FaceArrays extrapolated_;       // (3 u^n - u^{n-1}) / 2
  FrameForces frame_forces_;
  std::vector<double> pressure_;
  std::vector<double> cell_void_fraction_;      // ε^{n+1}
  std::vector<double> old_cell_void_fraction_;  // ε^n
  std::vector<double> cell_viscosity_;
  std::vector<double> phase_fraction_;  // α
  std::vector<double> cell_density_;
  FaceArrays face_density_;  // ρ_f: the mean of the two cells', the inner cell's on an outlet
  PhaseTransport phase_transport_;
  InterfaceCompression compression_;
  FaceArrays void_fraction_;      // ε_f^{n+1}
  FaceArrays old_void_fraction_;  // ε_f^n
  FaceArrays drag_coefficient_;
  FaceArrays grain_source_;
  FaceArrays convection_;
  FaceArrays transpose_;
  FaceArrays diagonal_;
  FaceArrays rhs_;
  FaceArrays coefficient_;
  std::vector<double> source_;
  std::vector<double> correction_;
  std::optional<materials::BoundedRheology> rheology_;  // none: Newtonian
  std::vector<double> shear_rate_;
  MomentumPredictor predictor_;
  PressureProjection projection_;
  LinearSolve momentum_solve_;
};

}  // namespace partimix::cfd
