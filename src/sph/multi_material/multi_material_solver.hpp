#pragma once
// The multi-material SPH scheme (docs/multi-material-sph.md, "The scheme"): compressible SPH
// with several materials in one run (Tait liquids, ideal and Redlich-Kwong gases, Johnson-Cook
// solids with damage), a variable smoothing length, the temperature from the energy equation
// with heat conduction, volumetric heat sources, heat through the surfaces of a material's bodies
// and the ambient's heat through the free surface,
// surface tension, and the kick-drift-kick leapfrog.
#include <memory>
#include <optional>
#include <string_view>
#include <vector>

#include "particles/cell_grid.hpp"
#include "particles/solver.hpp"
#include "sph/config.hpp"
#include "sph/kernel.hpp"
#include "sph/kernel_table.hpp"
#include "sph/multi_material/material.hpp"
#include "sph/multi_material/material_rates.hpp"
#include "sph/multi_material/surface_heating.hpp"
#include "sph/multi_material/total_lagrangian.hpp"
#include "sph/scaled_kernel.hpp"

namespace partimix::sph {

class MultiMaterialSolver final : public Solver {
 public:
  // `store` holds the particles, all of kind fluid, with position, velocity and mass set and an
  // integer field "material" (the index in config.multi_material.materials). The solver starts
  // each at its material's initial density and temperature and adds its own fields. Throws
  // InputError naming the case key when the configuration cannot be used.
  MultiMaterialSolver(ParticleStore& store, const Domain& domain, const Config& config,
                      const Vec3& gravity);

  std::string_view name() const override { return "sph"; }
  const ParticleStore& particles() const override { return store_; }
  const Domain& domain() const override { return domain_; }
  double stable_dt() const override { return stable_dt_; }
  void step(double dt) override;
  std::map<std::string, double> derived_parameters() const override;
  void save(StateArchive& archive, const std::string& prefix) const override;
  void restore(const StateArchive& archive, const std::string& prefix) override;

  const std::vector<Material>& materials() const { return materials_; }
  double time() const { return time_; }

 private:
  struct HalfStep {
    std::vector<Vec3> velocity;
    std::vector<double> density;
    std::vector<double> temperature;
    std::vector<Mat3> stress;
  };

  const Material& material_of(std::size_t i) const;
  void evaluate();
  void set_up_total_lagrangian();
  BondedParticles bonded_particles() const;
  void deform_solids();
  void take_solid_densities();
  bool density_follows_deformation(std::size_t i) const;
  bool broken(std::size_t i) const;
  void add_total_lagrangian_forces();
  void update_smoothing_lengths();
  double largest_grid_radius() const;
  void widen_grid(double largest_h);
  void update_state();
  void add_surface_tension();
  void update_temperature_rates();
  void update_stress_rates();
  void update_stable_dt();
  void kick(double dt);
  void drift(double dt);
  void yield_solids(double dt);
  void unload_loosened();
  void keep_half_step();
  void return_to_half_step();
  void write_stress_fields();
  void read_stress_fields();

  ParticleStore& store_;
  Domain domain_;
  Config config_;
  Vec3 gravity_;
  std::vector<Material> materials_;
  std::unique_ptr<Kernel> kernel_;
  ScaledKernel scaled_;
  KernelTable surface_table_;  // at the initial smoothing length, for surface tension
  std::optional<CellGrid> grid_;
  DensityPairing pairing_;
  ArtificialViscosity artificial_viscosity_;

  // Store fields: the state, and the last rates, which the next step's first kick uses.
  const std::vector<std::int32_t>& material_;
  std::vector<double>& density_;
  std::vector<double>& pressure_;  // above the ambient [Pa]
  std::vector<double>& temperature_;
  std::vector<double>& h_;
  std::vector<double>& damage_;
  std::vector<double>& plastic_strain_;
  std::vector<Vec3>& stress_normal_;  // S_xx, S_yy, S_zz
  std::vector<Vec3>& stress_shear_;   // S_xy, S_yz, S_zx
  std::vector<Vec3>& acceleration_;
  std::vector<double>& temperature_rate_;
  std::vector<double>& density_rate_;
  std::vector<Vec3>& stress_rate_normal_;
  std::vector<Vec3>& stress_rate_shear_;

  // Per-particle working arrays, sized once.
  std::vector<double> omega_, sound_speed_, spacing_, viscosity_, conductivity_;
  std::vector<double> expansion_, heating_, conduction_, colour_, curvature_, raw_curvature_;
  std::vector<double> momentum_pressure_;  // pressure + the background pressure
  std::vector<double> surface_source_;     // q'' S / V of SurfaceHeating [W/m^3]
  // Temperature boundaries (materials with fixed_temperature): each particle's flag, and the
  // temperatures conduction reads (sph/dirichlet_temperature.hpp).
  std::vector<std::uint8_t> held_;
  std::vector<double> conducted_temperature_;
  bool holds_temperatures_ = false;
  std::vector<Mat3> stress_, artificial_stress_, velocity_gradient_;
  std::vector<Vec3> unity_gradient_, colour_gradient_, normal_gradient_;
  HalfStep half_;

  // Total Lagrangian solids (absent without any): their particles' flags, reference volumes,
  // smoothing lengths and hourglass stiffnesses, Cauchy stress, and the store field
  // reference_position (their positions at the start).
  std::optional<TotalLagrangianSolids> total_lagrangian_;
  std::vector<std::uint8_t> bonded_;
  std::vector<double> reference_volume_, reference_h_, hourglass_;
  std::vector<Mat3> cauchy_;
  const std::vector<Vec3>* reference_ = nullptr;

  SurfaceHeating surface_heating_;
  bool conducts_ = false;  // some material conducts heat
  double time_ = 0.0;
  std::size_t steps_ = 0;
  double stable_dt_ = 0.0;
  double initial_dt_ = 0.0;
};

}  // namespace partimix::sph
