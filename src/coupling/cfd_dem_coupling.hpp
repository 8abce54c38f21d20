#pragma once
// The two-way coupling of the grid fluid and the DEM grains (docs/cfd-dem.md): at each exchange
// the grains' kernel weights on the open cells and faces, the void fraction the fluid steps to,
// the fluid's velocity, void fraction and pressure gradient gathered at each grain, the drag
// coefficient K_i of the chosen law, the grains' held forces (dem/external_forces.hpp), and the
// fluid's implicit drag K_f and explicit source S_e. The momentum the implicit split and the
// sub-cycles leave unbalanced over a step, D_i (from the impulse the grains actually received),
// is taken from the fluid over the next step, so fluid and grains together keep their momentum
// to round-off with the pressure-gradient force.
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
  CfdDemCoupling(cfd::CfdSolver& fluid, dem::DemSolver& grains, const CfdDemSettings& settings,
                 const Vec3& gravity);

  void exchange(double time, double dt) override;
  void save(StateArchive& archive, const std::string& prefix) const override;
  void restore(const StateArchive& archive, const std::string& prefix) override;

  // Σ_i D_i found at the last exchange: the momentum the fluid gives back over the next step.
  Vec3 deferred_momentum() const;
  // Cells whose void fraction was clipped to min_void_fraction at the last exchange, and grains
  // in no open cell (no force from the fluid).
  std::size_t clipped_cells() const { return clipped_; }
  std::size_t unmapped_grains() const { return cell_weights_.unmapped(); }
  double kernel_radius() const { return radius_; }

 private:
  struct Sample {  // the fluid at a grain
    Vec3 velocity = Vec3::Zero();
    Vec3 pressure_gradient = Vec3::Zero();
    double void_fraction = 1.0;
    bool mapped = true;  // false: the grain lies in no open cell
  };
  Sample sample(std::size_t row) const;
  void pressure_gradients();
  void settle_last_step();
  void map_grains();
  void map_void_fraction(std::span<const std::int64_t> ids);
  void set_grain_forces(double dt);
  void set_fluid_source(double dt);

  cfd::CfdSolver& fluid_;
  dem::DemSolver& grains_;
  dem::ExternalForces external_;
  CfdDemSettings settings_;
  Vec3 gravity_;
  std::unique_ptr<DragLaw> law_;
  double radius_ = 0.0;
  std::vector<double> volumes_;    // V_i by grain id
  std::vector<double> diameters_;  // d_i by grain id
  KernelWeights cell_weights_;
  FaceWeights face_weights_;
  std::vector<double> void_fraction_;  // the cells', as given to the fluid
  std::vector<double> row_volumes_;    // V_i in the grains' present order
  cfd::FaceArrays gradient_;           // (∇p)_f at the exchange
  std::size_t clipped_ = 0;
  // Per row of the last exchange (the grains' order then): id, position, velocity, K_i and the
  // held force other than the drag; D_i in the grains' present order.
  std::vector<std::int64_t> ids_;
  std::vector<Vec3> positions_;
  std::vector<Vec3> velocities_;
  std::vector<double> drag_;
  std::vector<Vec3> other_force_;
  std::vector<Vec3> deferred_;
  std::vector<std::size_t> index_of_id_;  // the grains' present order
  bool started_ = false;
  double last_dt_ = 0.0;
};

}  // namespace partimix::coupling
