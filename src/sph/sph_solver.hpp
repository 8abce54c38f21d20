#pragma once
// Weakly-compressible SPH for Newtonian free-surface flow (docs/sph.md): the seed's eqs. 1-3,
// 8-13 and 17-20 with Adami walls, delta-SPH, and the symplectic predictor-corrector of
// Monaghan (2005) / DualSPHysics with adaptive time step.
#include <memory>
#include <optional>
#include <string_view>
#include <vector>

#include "geometry/moving_bodies.hpp"
#include "materials/rheology.hpp"
#include "particles/cell_grid.hpp"
#include "particles/neighbour_list.hpp"
#include "particles/solver.hpp"
#include "sph/config.hpp"
#include "sph/equation_of_state.hpp"
#include "sph/fields.hpp"
#include "sph/fluid_rates.hpp"
#include "sph/implicit_viscosity.hpp"
#include "sph/kernel.hpp"
#include "sph/kernel_table.hpp"
#include "sph/parameters.hpp"
#include "sph/particle_shifting.hpp"
#include "sph/pressure_poisson.hpp"

namespace partimix::sph {

struct FluidProperties {
  double density = 1000.0;             // rho0 [kg/m^3]
  materials::RheologyConfig rheology;  // apparent viscosity model
};

class SphSolver final : public Solver {
 public:
  // `store` holds fluid and wall particles with kind and position set. The solver sets masses
  // (rho0 dp^d), hydrostatic initial densities and its own fields. Throws InputError
  // naming the case key when the configuration cannot be used (e.g. no way to set c0).
  // `bodies` (may be null) moves the wall particles of bodies with prescribed motions; it
  // must outlive the solver.
  SphSolver(ParticleStore& store, const Domain& domain, const Config& config,
            const FluidProperties& fluid, const Vec3& gravity,
            geometry::MovingBodies* bodies = nullptr);

  std::string_view name() const override { return "sph"; }
  const ParticleStore& particles() const override { return store_; }
  const Domain& domain() const override { return domain_; }
  double stable_dt() const override;
  void step(double dt) override;
  std::map<std::string, double> derived_parameters() const override;
  void update_body_forces() override;
  void save(StateArchive& archive, const std::string& prefix) const override;
  void restore(const StateArchive& archive, const std::string& prefix) override;

  const Parameters& parameters() const { return parameters_; }

 private:
  void initialise_fluid();
  void interact();
  void update_smoothing_lengths();
  void widen_search(double largest_h);
  RateExtremes fluid_rates();
  void predict(double dt);
  void correct(double dt);
  void advance_weakly_compressible(double dt);
  void advance_incompressible(double dt);
  void refresh_incompressible();
  void predict_viscous_explicit(double dt);
  void predict_viscous_implicit(double dt);
  bool update_apparent_viscosity();
  void stop_unless_converged(const LinearSolve& solve, std::string_view what) const;
  void shift_particles_after_step(double dt);
  void wrap_positions();
  void move_bodies(double time);
  void sort_by_cell();
  void warn_once_if_too_fast();
  void update_viscosity();

  ParticleStore& store_;
  Domain domain_;
  Config config_;
  Parameters parameters_;
  Fields fields_;
  std::unique_ptr<Kernel> kernel_;
  std::unique_ptr<Kernel> gradient_kernel_;
  std::unique_ptr<EquationOfState> eos_;
  KernelTable kernel_table_;
  KernelTable gradient_table_;
  CellGrid grid_;
  NeighbourList neighbours_;  // fluid pairs and fluid-wall pairs of the fluid rates
  RateBuffers rate_buffers_;
  double max_acceleration_ = 0.0;
  double max_speed_ = 0.0;
  std::size_t steps_ = 0;
  double time_ = 0.0;
  geometry::MovingBodies* bodies_;
  bool warned_about_speed_ = false;
  bool warned_about_picard_ = false;
  double initial_dt_ = 0.0;  // the stable step at t = 0, for run.json (derived_parameters)
  materials::BoundedRheology rheology_;
  bool newtonian_ = true;
  double max_viscosity_ = 0.0;   // largest apparent viscosity of the fluid now [Pa s]
  std::size_t fluid_count_ = 0;  // fluid particles are [0, fluid_count_) of the store
  std::vector<std::uint32_t> sort_order_;
  std::vector<Vec3> start_position_;
  std::vector<Vec3> start_velocity_;
  std::vector<double> start_density_;
  std::vector<double> scratch_;
  std::vector<double> previous_viscosity_;  // of the last Picard iterate
  std::vector<Vec3> stress_rates_;  // div(eta G^T) / rho, the semi-implicit step's explicit part
  ShiftingScratch shifting_;
  // The incompressible scheme's pressure solve; absent for the weakly-compressible one.
  std::optional<PressurePoisson> poisson_;
  std::optional<ImplicitViscosity> viscous_;  // with sph.viscosity_integration: implicit
  double flow_speed_estimate_ = 0.0;          // U of the incompressible time step [m/s]
  std::vector<Vec3>* body_force_ = nullptr;   // store fields, when there are bodies
  std::vector<Vec3>* body_couple_ = nullptr;
  // sph.smoothing_length: variable: each particle's h_i (a store field) and the smallest [m].
  std::vector<double>* smoothing_length_ = nullptr;
  double smallest_smoothing_length_ = 0.0;
  double reach_ = 1.0;  // of the grid and neighbour list, in reference supports
};

}  // namespace partimix::sph
