#pragma once
// The two-way coupling of the grid fluid and the DEM grains (docs/cfd-dem.md, "One coupled
// step"): the fluid steps first, then the grains. Before the fluid steps, the grains are mapped
// where they are: their kernel weights, the void fraction the fluid steps to, the drag
// coefficient K_i of the chosen law from the fluid's present velocity, and the fluid's implicit
// drag K_f and explicit source S_e. Before the grains step, the fluid's new velocity and pressure
// gradient are gathered at each grain with the same weights, and the grains are given their held
// forces (dem/external_forces.hpp). The momentum the sub-cycles leave unbalanced over a step,
// D_i = J_i - (what the fluid's step gave grain i), from the impulse J_i the grains actually
// received, is taken from the fluid over the next step, so fluid and grains together keep their
// momentum to round-off with the pressure-gradient force. In a rotating frame (cfd.rotating_frame)
// the grains are mapped at their places in the frame as it stands when the coupled step begins,
// and the fluid's values turned into the lab for them (docs/cfd-dem.md, "Rotating frame").
#include <cstddef>
#include <memory>
#include <span>
#include <vector>

#include "cfd/cfd_solver.hpp"
#include "coupling/cfd_dem_settings.hpp"
#include "coupling/coupling.hpp"
#include "coupling/drag_law.hpp"
#include "coupling/face_weights.hpp"
#include "coupling/kernel_weights.hpp"
#include "dem/dem_solver.hpp"

namespace partimix::coupling {

class CfdDemCoupling final : public Coupling {
 public:
  // `fluid_method` and `grain_method`: the methods' indices in the case's `solver`; `grain_store`
  // the grains' store, which gets the fields fluid_void_fraction and fluid_force for the frames.
  CfdDemCoupling(cfd::CfdSolver& fluid, std::size_t fluid_method, dem::DemSolver& grains,
                 std::size_t grain_method, ParticleStore& grain_store,
                 const CfdDemSettings& settings, const Vec3& gravity);

  void before_method(std::size_t m, double time, double dt) override;
  std::map<std::string, double> derived_parameters() const override {
    return {{"kernel radius [m]", radius_}};
  }
  void save(StateArchive& archive, const std::string& prefix) const override;
  void restore(const StateArchive& archive, const std::string& prefix) override;

  // Before the fluid steps at `time`: D_i of the last step, the grains' void fraction and drag.
  void exchange_with_fluid(double time, double dt);
  // Before the grains step: their held forces from the fluid's new state.
  void exchange_with_grains(double dt);

  // Σ_i D_i found before the fluid's last step: the momentum it gives back over that step.
  Vec3 deferred_momentum() const;
  // Cells whose void fraction was clipped to min_void_fraction at the last mapping, and grains
  // in no open cell (no force from the fluid).
  std::size_t clipped_cells() const { return clipped_; }
  std::size_t unmapped_grains() const { return cell_weights_.unmapped(); }
  double kernel_radius() const { return radius_; }

 private:
  struct Sample {  // the fluid at a grain
    Vec3 velocity = Vec3::Zero();
    Vec3 pressure_gradient = Vec3::Zero();
    double void_fraction = 1.0;
    double viscosity = 0.0;  // η of the fluid's cells around the grain
    double density = 0.0;    // ρ of the fluid's cells around the grain (two phases: the mixture)
    bool mapped = true;      // false: the grain lies in no open cell
  };
  Sample sample(std::size_t p, bool with_pressure) const;
  void pressure_gradients();
  void map_grains();
  void settle_last_step(double dt);
  void follow_grains(double dt);
  void set_drag();
  void set_grain_forces(double dt);
  Vec3 virtual_mass(std::size_t p, std::size_t id, const Sample& s, double dt) const;
  void set_fluid_source(double dt);
  // The grain's velocity relative to the frame, in its directions.
  Vec3 relative_velocity(std::size_t p) const;

  cfd::CfdSolver& fluid_;
  std::size_t fluid_method_;
  dem::DemSolver& grains_;
  std::size_t grain_method_;
  dem::ExternalForces external_;
  std::vector<double>* grain_void_fraction_;  // ε at each grain, for the frames
  std::vector<Vec3>* grain_fluid_force_;      // the fluid's force on each grain as set [N]
  CfdDemSettings settings_;
  Vec3 gravity_;
  std::unique_ptr<DragLaw> law_;
  double radius_ = 0.0;
  std::vector<double> volumes_;    // V_i by grain id
  std::vector<double> diameters_;  // d_i by grain id
  KernelWeights cell_weights_;     // of the grains where they were last mapped
  FaceWeights face_weights_;
  std::vector<double> void_fraction_;  // the cells', as last mapped
  std::vector<double> row_volumes_;    // V_i in the grains' order when mapped
  std::vector<double> row_radii_;      // the radius of V_i's sphere, likewise
  geometry::RigidPose frame_;          // the fluid's frame when the coupled step began
  std::vector<Vec3> frame_positions_;  // the grains' places in the frame when mapped
  std::vector<Vec3> pushes_;           // K_i v_i - D_i / Δt per grain, in the frame
  cfd::FaceArrays gradient_;           // (∇p)_f before the grains step
  std::size_t clipped_ = 0;
  // Per grain in the order of the last mapping (the grains do not move before they step):
  // K_i, v_i as the fluid's step used them, D_i; and the grains' held force other than the drag
  // and the fluid's velocity at them as they stepped with, with their ids.
  std::vector<double> drag_;
  std::vector<Vec3> velocities_;
  std::vector<Vec3> deferred_;
  std::vector<std::int64_t> ids_;
  std::vector<Vec3> fluid_velocities_;
  std::vector<Vec3> other_force_;
  std::vector<Vec3> pressure_force_;  // the part of other_force_ the fluid's step gave
  // Before the fluid's step, in the grains' present order: the fluid's velocity at each grain as
  // it last stepped with, and its acceleration over that step (the virtual mass).
  std::vector<Vec3> previous_fluid_velocities_;
  std::vector<Vec3> accelerations_;
  std::vector<std::size_t> row_of_id_;
  bool started_ = false;
  double last_dt_ = 0.0;
};

}  // namespace partimix::coupling
