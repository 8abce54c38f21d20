#include "sph/multi_material/multi_material_solver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>

#include "core/error.hpp"
#include "materials/artificial_stress.hpp"
#include "materials/jaumann_rate.hpp"
#include "particles/store_state.hpp"
#include "sph/dirichlet_temperature.hpp"
#include "sph/heat_conduction.hpp"
#include "sph/multi_material/solid_update.hpp"
#include "sph/smoothing_length.hpp"
#include "sph/surface_tension.hpp"

namespace partimix::sph {
namespace {

// The grid's radius is this much above the widest support, so that h may grow a while before
// the grid is laid out again.
constexpr double kGridMargin = 1.25;
// Surface tension acts where |grad C| h exceeds this (sph/surface_tension.hpp).
constexpr double kInterfaceThreshold = 0.05;

Vec3 normal_part(const Mat3& s) {
  return {s(0, 0), s(1, 1), s(2, 2)};
}
Vec3 shear_part(const Mat3& s) {
  return {s(0, 1), s(1, 2), s(2, 0)};
}

Mat3 symmetric(const Vec3& normal, const Vec3& shear) {
  Mat3 s;
  s << normal[0], shear[0], shear[2], shear[0], normal[1], shear[1], shear[2], shear[1], normal[2];
  return s;
}

std::unique_ptr<Kernel> make_kernel(const std::string& name) {
  auto kernel = kernel_registry().create(name);
  if (!kernel)
    throw InputError(InputLocation{"", 0, 0, "sph.kernel"}, "unknown kernel '" + name + "'");
  return kernel;
}

std::vector<double> surface_heat_fluxes(const MultiMaterialSettings& settings) {
  std::vector<double> flux;
  for (const MaterialSpec& spec : settings.materials)
    flux.push_back(spec.surface_heat_flux);
  return flux;
}

const std::vector<std::int32_t>& material_field(const ParticleStore& store) {
  const Field<std::int32_t>* field = store.find_integer("material");
  if (field == nullptr)
    throw std::logic_error("multi-material SPH: the store has no field 'material'");
  return field->values;
}

}  // namespace

MultiMaterialSolver::MultiMaterialSolver(ParticleStore& store, const Domain& domain,
                                         const Config& config, const Vec3& gravity)
    : store_(store),
      domain_(domain),
      config_(config),
      gravity_(gravity),
      materials_(build_materials(config.multi_material)),
      kernel_(make_kernel(config.kernel)),
      scaled_(*kernel_, domain.dimensions),
      surface_table_(*kernel_, config.multi_material.eta * config.spacing, domain.dimensions),
      pairing_(config.multi_material.density == "summation" ? DensityPairing::summation
                                                            : DensityPairing::continuity),
      artificial_viscosity_{config.multi_material.alpha, config.multi_material.beta},
      material_(material_field(store)),
      density_(store.add_scalar("density", "kg/m^3").values),
      pressure_(store.add_scalar("pressure", "Pa").values),
      temperature_(store.add_scalar("temperature", "K").values),
      h_(store.add_scalar("smoothing_length", "m").values),
      damage_(store.add_scalar("damage", "").values),
      plastic_strain_(store.add_scalar("plastic_strain", "").values),
      stress_normal_(store.add_vector("deviatoric_stress_normal", "Pa").values),
      stress_shear_(store.add_vector("deviatoric_stress_shear", "Pa").values),
      acceleration_(store.add_vector("acceleration", "m/s^2", false).values),
      temperature_rate_(store.add_scalar("temperature_rate", "K/s", false).values),
      density_rate_(store.add_scalar("density_rate", "kg/(m^3 s)", false).values),
      stress_rate_normal_(store.add_vector("stress_rate_normal", "Pa/s", false).values),
      stress_rate_shear_(store.add_vector("stress_rate_shear", "Pa/s", false).values),
      surface_heating_(surface_heat_fluxes(config.multi_material), domain.dimensions) {
  const std::size_t n = store_.size();
  for (std::vector<double>* array :
       {&omega_, &sound_speed_, &spacing_, &viscosity_, &conductivity_, &expansion_, &heating_,
        &conduction_, &colour_, &curvature_, &raw_curvature_, &momentum_pressure_, &surface_source_,
        &conducted_temperature_})
    array->assign(n, 0.0);
  held_.assign(n, 0);
  for (std::vector<Mat3>* array : {&stress_, &artificial_stress_, &velocity_gradient_})
    array->assign(n, Mat3::Zero());
  for (std::vector<Vec3>* array : {&unity_gradient_, &colour_gradient_, &normal_gradient_})
    array->assign(n, Vec3::Zero());
  const double inverse_d = 1.0 / domain_.dimensions;
  double largest_h = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!store_.is_fluid(i))
      throw std::logic_error("multi-material SPH: a particle is not of kind fluid");
    const Material& material = material_of(i);
    density_[i] = material.initial_density();
    temperature_[i] = material.spec().temperature;
    h_[i] = config.multi_material.eta * std::pow(store_.mass()[i] / density_[i], inverse_d);
    omega_[i] = 1.0;
    viscosity_[i] = material.spec().viscosity;
    conductivity_[i] = material.spec().conductivity;
    held_[i] = material.spec().fixed_temperature ? 1 : 0;
    largest_h = std::max(largest_h, h_[i]);
  }
  holds_temperatures_ = std::find(held_.begin(), held_.end(), 1) != held_.end();
  conducts_ =
      std::any_of(conductivity_.begin(), conductivity_.end(), [](double k) { return k > 0.0; });
  largest_h = std::max(largest_h, surface_table_.support_radius() / scaled_.support());
  widen_grid(largest_h);
  set_up_total_lagrangian();
  evaluate();
  initial_dt_ = stable_dt_;
}

const Material& MultiMaterialSolver::material_of(std::size_t i) const {
  return materials_[static_cast<std::size_t>(material_[i])];
}

// Flags the particles of total Lagrangian solids and keeps their reference state: the volume
// m / rho0 and smoothing length at the start, and the positions as the store field
// reference_position (restored with the rest from a checkpoint).
void MultiMaterialSolver::set_up_total_lagrangian() {
  const std::size_t n = store_.size();
  bonded_.assign(n, 0);
  double largest_h = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const auto& solid = material_of(i).spec().solid;
    if (solid && solid->total_lagrangian) {
      bonded_[i] = 1;
      largest_h = std::max(largest_h, h_[i]);
    }
  }
  if (largest_h == 0.0)
    return;
  for (const bool periodic : domain_.periodic) {
    if (periodic) {
      throw InputError(InputLocation{"", 0, 0, "sph.materials"},
                       "a solid of formulation total_lagrangian needs a domain without periodic "
                       "axes");
    }
  }
  reference_volume_.assign(n, 0.0);
  for (std::size_t i = 0; i < n; ++i)
    reference_volume_[i] = store_.mass()[i] / density_[i];
  reference_h_ = h_;
  hourglass_.assign(n, 0.0);
  cauchy_.assign(n, Mat3::Zero());
  std::vector<Vec3>& reference = store_.add_vector("reference_position", "m", false).values;
  reference = store_.position();
  reference_ = &reference;
  total_lagrangian_.emplace(domain_, scaled_, largest_h);
  total_lagrangian_->refer(bonded_particles(), n);
}

BondedParticles MultiMaterialSolver::bonded_particles() const {
  return {store_.position(), store_.velocity(), *reference_, store_.mass(), reference_volume_,
          reference_h_,      bonded_,           cauchy_,     hourglass_,    damage_};
}

// F and L of the total Lagrangian solids, and their density from F.
void MultiMaterialSolver::deform_solids() {
  total_lagrangian_->deform(bonded_particles(), store_.size());
  take_solid_densities();
}

// The total Lagrangian solids' density from their last F: rho = m / (V0 det F), so that their
// pressure follows the deformation their stress force is taken from.
void MultiMaterialSolver::take_solid_densities() {
  const std::span<const Mat3> deformation = total_lagrangian_->deformation_gradient();
  for (std::size_t i = 0; i < store_.size(); ++i) {
    if (density_follows_deformation(i))
      density_[i] = store_.mass()[i] / (reference_volume_[i] * deformation[i].determinant());
  }
}

// Whether particle i's density comes from its F: a total Lagrangian solid's particle, unless
// broken; a failed particle has no bonds to take F from and keeps the continuity density.
bool MultiMaterialSolver::density_follows_deformation(std::size_t i) const {
  return total_lagrangian_ && bonded_[i] && !broken(i);
}

// Whether particle i carries no deviatoric stress and, in tension, no pressure: fully damaged,
// or a total Lagrangian solid's particle that a crack loosened (total_lagrangian.hpp).
bool MultiMaterialSolver::broken(std::size_t i) const {
  return damage_[i] >= 1.0 || (total_lagrangian_ && total_lagrangian_->failed(i));
}

// The total Lagrangian solids' L, replacing the updated Lagrangian one, and their bonded pairs'
// forces; after deform_solids().
void MultiMaterialSolver::add_total_lagrangian_forces() {
  const std::span<const Mat3> rate = total_lagrangian_->velocity_gradient();
  const BondedParticles bonded = bonded_particles();
  for (std::size_t i = 0; i < store_.size(); ++i) {
    if (total_lagrangian_->holds(bonded, i))
      velocity_gradient_[i] = rate[i];
  }
  total_lagrangian_->add_forces(bonded, store_.size(), acceleration_);
}

// The largest radius a grid may have: a third of the shortest periodic axis.
double MultiMaterialSolver::largest_grid_radius() const {
  double allowed = std::numeric_limits<double>::infinity();
  for (int axis = 0; axis < domain_.dimensions; ++axis) {
    if (domain_.periodic[static_cast<std::size_t>(axis)])
      allowed = std::min(allowed, (1.0 - 1e-9) * (domain_.hi[axis] - domain_.lo[axis]) / 3.0);
  }
  return allowed;
}

// A grid whose radius covers support * largest_h, with kGridMargin to spare where the domain's
// periodic axes allow it.
void MultiMaterialSolver::widen_grid(double largest_h) {
  const double required = scaled_.support() * largest_h;
  const double allowed = largest_grid_radius();
  if (allowed < required || (grid_ && grid_->radius() >= allowed)) {
    throw RunError(fmt::format(
        "multi-material SPH at t = {:.6g} s: the smoothing length grew to {:.6g} m, whose "
        "support is more than a third of a periodic axis",
        time_, largest_h));
  }
  grid_.emplace(domain_, std::min(allowed, kGridMargin * required));
}

// Rates at the current state: smoothing lengths (and the summation density), pressures, then
// the pair sums, surface tension and the temperature and stress rates.
void MultiMaterialSolver::evaluate() {
  grid_->build(store_.position());
  update_smoothing_lengths();
  if (total_lagrangian_)
    deform_solids();
  update_state();
  const std::size_t n = store_.size();
  MaterialParticles particles{store_.position(),  store_.velocity(),
                              store_.mass(),      h_,
                              density_,           omega_,
                              momentum_pressure_, stress_,
                              artificial_stress_, spacing_,
                              sound_speed_,       viscosity_};
  particles.bonds = total_lagrangian_ ? &total_lagrangian_->bonds() : nullptr;
  material_rates(particles, n, *grid_, scaled_, pairing_, artificial_viscosity_,
                 {acceleration_, expansion_, heating_, velocity_gradient_, unity_gradient_});
  if (total_lagrangian_)
    add_total_lagrangian_forces();
  for (Vec3& a : acceleration_)
    a += gravity_;
  add_surface_tension();
  update_temperature_rates();
  update_stress_rates();
  update_stable_dt();
}

void MultiMaterialSolver::update_smoothing_lengths() {
  const std::size_t n = store_.size();
  const int d = domain_.dimensions;
  if (pairing_ == DensityPairing::continuity) {
    double largest = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      h_[i] = config_.multi_material.eta * std::pow(store_.mass()[i] / density_[i], 1.0 / d);
      largest = std::max(largest, h_[i]);
    }
    if (scaled_.support() * largest > grid_->radius()) {
      widen_grid(largest);
      grid_->build(store_.position());
    }
    return;
  }
  SmoothingLengthSettings settings;
  settings.eta = config_.multi_material.eta;
  for (int attempt = 0; attempt < 4; ++attempt) {
    const SmoothingLengthSolve solve = solve_smoothing_lengths(
        settings, {store_.position(), store_.mass(), h_, density_, omega_}, n, *grid_, scaled_, d);
    if (solve.failed == 0)
      return;
    widen_grid(std::min(kGridMargin * grid_->radius(), largest_grid_radius()) / scaled_.support());
    grid_->build(store_.position());
  }
  throw RunError(fmt::format(
      "multi-material SPH at t = {:.6g} s: the smoothing lengths did not converge", time_));
}

// Pressure above the ambient, sound speed, the solids' stress and artificial stress.
void MultiMaterialSolver::update_state() {
  const double ambient = config_.multi_material.ambient.pressure;
  const double inverse_d = 1.0 / domain_.dimensions;
  for (std::size_t i = 0; i < store_.size(); ++i) {
    const double rho = density_[i];
    const double t = temperature_[i];
    if (!(rho > 0.0 && std::isfinite(rho) && t > 0.0 && std::isfinite(t))) {
      throw RunError(fmt::format(
          "multi-material SPH at t = {:.6g} s: particle {} reached density {:.6g} kg/m^3 and "
          "temperature {:.6g} K; the time step is too long for the forces, or a material's "
          "state left its equation of state's range",
          time_, store_.id()[i], rho, t));
    }
    const Material& material = material_of(i);
    const MaterialSpec& spec = material.spec();
    double gauge = material.absolute_pressure(rho, t) - ambient;
    if (broken(i))
      gauge = std::max(gauge, 0.0);
    pressure_[i] = gauge;
    momentum_pressure_[i] = gauge + config_.multi_material.background_pressure;
    double c2 =
        std::pow(materials::adiabatic_sound_speed(material.eos(), rho, t, spec.specific_heat), 2);
    if (spec.solid) {
      const double shear = spec.solid->shear_modulus;
      const double bulk = rho * c2;
      c2 += 4.0 * shear / (3.0 * rho);
      const Mat3 sigma = stress_[i] - gauge * Mat3::Identity();
      artificial_stress_[i] =
          materials::artificial_stress(sigma, rho, spec.solid->artificial_stress);
      if (total_lagrangian_ && bonded_[i]) {
        cauchy_[i] = stress_[i] - momentum_pressure_[i] * Mat3::Identity();
        hourglass_[i] = spec.solid->hourglass * 9.0 * bulk * shear / (3.0 * bulk + shear);
      }
    }
    sound_speed_[i] = std::sqrt(c2);
    spacing_[i] = std::pow(store_.mass()[i] / rho, inverse_d);
  }
}

// Surface tension of each material that has one, on its boundary with the rest (the colour 1
// on the material, 0 elsewhere), at the initial smoothing length.
void MultiMaterialSolver::add_surface_tension() {
  const std::size_t n = store_.size();
  const double h = surface_table_.support_radius() / scaled_.support();
  for (std::size_t m = 0; m < materials_.size(); ++m) {
    const double sigma = materials_[m].spec().surface_tension;
    if (sigma <= 0.0)
      continue;
    for (std::size_t i = 0; i < n; ++i)
      colour_[i] = static_cast<std::size_t>(material_[i]) == m ? 1.0 : 0.0;
    const InterfaceParticles particles{store_.position(), store_.mass(), density_, colour_};
    compute_colour_gradients(particles, n, *grid_, surface_table_, true, colour_gradient_);
    compute_colour_gradients(particles, n, *grid_, surface_table_, false, normal_gradient_);
    compute_curvatures(particles, n, *grid_, surface_table_, domain_.dimensions, h,
                       kInterfaceThreshold, normal_gradient_, raw_curvature_);
    smooth_curvatures(particles, n, *grid_, surface_table_, normal_gradient_, raw_curvature_,
                      curvature_);
    sph::add_surface_tension(particles, n, sigma, colour_gradient_, curvature_, acceleration_);
  }
}

// c_v dT/dt = T (dp/dT)_rho epsilon + heating + conduction + (q + q'' S / V) / rho + the ambient's
// heat h (T_a - T) 2 |g| / rho, 2 |g| the surface per unit volume (the particles hold only the
// inner half of the colour's step from 1 to 0) (docs/multi-material-sph.md, "The scheme"); 0 for
// a material with a fixed temperature.
// With the continuity pairing, drho/dt = rho^2 epsilon.
void MultiMaterialSolver::update_temperature_rates() {
  const std::size_t n = store_.size();
  std::fill(conduction_.begin(), conduction_.end(), 0.0);
  if (conducts_) {
    std::span<const double> conducted = temperature_;
    if (holds_temperatures_) {
      dirichlet_temperatures({store_.position(), h_, temperature_, held_}, n, *grid_, scaled_,
                             conducted_temperature_);
      conducted = conducted_temperature_;
    }
    add_conduction_rates({store_.position(), h_, store_.mass(), density_, conducted, conductivity_},
                         n, *grid_, scaled_, conduction_);
  }
  if (surface_heating_.any()) {
    surface_heating_.update({store_.position(), h_, store_.mass(), density_, material_}, n, *grid_,
                            surface_source_);
  }
  const Ambient& ambient = config_.multi_material.ambient;
  for (std::size_t i = 0; i < n; ++i) {
    const MaterialSpec& spec = material_of(i).spec();
    const double rho = density_[i];
    const double t = temperature_[i];
    const double work =
        t * material_of(i).eos().pressure_temperature_derivative(rho, t) * expansion_[i];
    const double surface_heat = ambient.heat_transfer_coefficient * (ambient.temperature - t) *
                                2.0 * unity_gradient_[i].norm() / rho;
    temperature_rate_[i] = spec.fixed_temperature
                               ? 0.0
                               : (work + heating_[i] + conduction_[i] +
                                  (spec.heat_source + surface_source_[i]) / rho + surface_heat) /
                                     spec.specific_heat;
    density_rate_[i] = pairing_ == DensityPairing::continuity ? rho * rho * expansion_[i] : 0.0;
    // A total Lagrangian solid's density follows det F (deform_solids()); between evaluations
    // it moves at the rate of its own L.
    if (density_follows_deformation(i))
      density_rate_[i] = -rho * velocity_gradient_[i].trace();
  }
}

void MultiMaterialSolver::update_stress_rates() {
  for (std::size_t i = 0; i < store_.size(); ++i) {
    const auto& solid = material_of(i).spec().solid;
    const Mat3 rate = solid && !broken(i)
                          ? materials::jaumann_stress_rate(stress_[i], velocity_gradient_[i],
                                                           solid->shear_modulus)
                          : Mat3::Zero();
    stress_rate_normal_[i] = normal_part(rate);
    stress_rate_shear_[i] = shear_part(rate);
  }
}

// The smallest of the acoustic, force, viscous, conductive and capillary limits
// (docs/multi-material-sph.md, "The scheme").
void MultiMaterialSolver::update_stable_dt() {
  const TimeStepFactors& f = config_.time_step;
  double dt = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < store_.size(); ++i) {
    const MaterialSpec& spec = material_of(i).spec();
    const double h = h_[i];
    const double rho = density_[i];
    dt = std::min(dt, f.cfl * h / (sound_speed_[i] + store_.velocity()[i].norm()));
    const double a = acceleration_[i].norm();
    if (a > 0.0)
      dt = std::min(dt, f.force * std::sqrt(h / a));
    if (spec.viscosity > 0.0)
      dt = std::min(dt, f.viscous * rho * h * h / spec.viscosity);
    if (spec.conductivity > 0.0)
      dt = std::min(dt, f.conductive * rho * spec.specific_heat * h * h / spec.conductivity);
    if (spec.surface_tension > 0.0) {
      dt = std::min(dt, f.capillary * std::sqrt(rho * h * h * h /
                                                (2.0 * std::numbers::pi * spec.surface_tension)));
    }
  }
  stable_dt_ = dt;
}

// Kick-drift-kick (docs/multi-material-sph.md, "The scheme"): the rates at the new positions
// are taken with the velocity, density, temperature and stress predicted to the step's end,
// then the second half kick starts again from the half step's values. Total Lagrangian solids
// take their density from F at the step's end positions, those of the evaluation. The solids
// then return to their yield surface and accumulate damage, and the fully damaged ones crack.
void MultiMaterialSolver::step(double dt) {
  kick(0.5 * dt);
  drift(dt);
  keep_half_step();
  kick(0.5 * dt);
  evaluate();
  return_to_half_step();
  kick(0.5 * dt);
  if (total_lagrangian_)
    take_solid_densities();
  yield_solids(dt);
  if (total_lagrangian_) {
    total_lagrangian_->crack(bonded_particles(), store_.size());
    unload_loosened();
  }
  write_stress_fields();
  time_ += dt;
  ++steps_;
}

void MultiMaterialSolver::kick(double dt) {
  const bool continuity = pairing_ == DensityPairing::continuity;
  for (std::size_t i = 0; i < store_.size(); ++i) {
    store_.velocity()[i] += dt * acceleration_[i];
    temperature_[i] += dt * temperature_rate_[i];
    if (continuity)
      density_[i] += dt * density_rate_[i];
    stress_[i] += dt * symmetric(stress_rate_normal_[i], stress_rate_shear_[i]);
  }
}

void MultiMaterialSolver::drift(double dt) {
  for (std::size_t i = 0; i < store_.size(); ++i) {
    Vec3& x = store_.position()[i];
    x += dt * store_.velocity()[i];
    domain_.wrap(x);
    if (!domain_.contains(x)) {
      throw RunError(fmt::format(
          "multi-material SPH at t = {:.6g} s: particle {} left the domain at ({:.6g}, {:.6g}, "
          "{:.6g}); enlarge domain.min/max",
          time_, store_.id()[i], x.x(), x.y(), x.z()));
    }
  }
}

void MultiMaterialSolver::keep_half_step() {
  half_.velocity = store_.velocity();
  half_.density = density_;
  half_.temperature = temperature_;
  half_.stress = stress_;
}

void MultiMaterialSolver::return_to_half_step() {
  std::copy(half_.velocity.begin(), half_.velocity.end(), store_.velocity().begin());
  if (pairing_ == DensityPairing::continuity)
    density_ = half_.density;
  temperature_ = half_.temperature;
  stress_ = half_.stress;
}

void MultiMaterialSolver::yield_solids(double dt) {
  for (std::size_t i = 0; i < store_.size(); ++i) {
    const MaterialSpec& spec = material_of(i).spec();
    if (!spec.solid)
      continue;
    if (broken(i)) {
      stress_[i].setZero();
      continue;
    }
    SolidPoint point{stress_[i], plastic_strain_[i], damage_[i]};
    const SolidStepResult result = return_to_yield(*spec.solid, stress_[i], pressure_[i],
                                                   temperature_[i], density_[i], dt, point);
    stress_[i] = point.deviatoric_stress;
    plastic_strain_[i] = point.plastic_strain;
    damage_[i] = point.damage;
    if (!spec.fixed_temperature)
      temperature_[i] += result.plastic_work / spec.specific_heat;
  }
}

// The particles a crack left too few bonds to hold (total_lagrangian.hpp) are broken from now on:
// they shed their deviatoric stress, and keep their damage.
void MultiMaterialSolver::unload_loosened() {
  for (const std::size_t k : total_lagrangian_->loosened())
    stress_[k].setZero();
}

void MultiMaterialSolver::write_stress_fields() {
  for (std::size_t i = 0; i < store_.size(); ++i) {
    stress_normal_[i] = normal_part(stress_[i]);
    stress_shear_[i] = shear_part(stress_[i]);
  }
}

void MultiMaterialSolver::read_stress_fields() {
  for (std::size_t i = 0; i < store_.size(); ++i)
    stress_[i] = symmetric(stress_normal_[i], stress_shear_[i]);
}

std::map<std::string, double> MultiMaterialSolver::derived_parameters() const {
  std::map<std::string, double> parameters{
      {"particles [-]", static_cast<double>(store_.size())},
      {"initial_time_step [s]", initial_dt_},
      {"smoothing_length_max [m]", *std::max_element(h_.begin(), h_.end())}};
  for (const Material& material : materials_) {
    const MaterialSpec& spec = material.spec();
    const double rho = material.initial_density();
    const std::string prefix = "material " + spec.name + " ";
    parameters[prefix + "initial_density [kg/m^3]"] = rho;
    parameters[prefix + "initial_pressure [Pa]"] =
        material.absolute_pressure(rho, spec.temperature);
    parameters[prefix + "sound_speed [m/s]"] =
        materials::adiabatic_sound_speed(material.eos(), rho, spec.temperature, spec.specific_heat);
  }
  return parameters;
}

// The store holds the state and the last rates; with the grid's radius, time, step count and
// stable step the next step is the uninterrupted run's.
void MultiMaterialSolver::save(StateArchive& archive, const std::string& prefix) const {
  save_store(store_, archive, prefix);
  archive.put_scalar(prefix + "time", time_);
  archive.put_scalar(prefix + "steps", static_cast<double>(steps_));
  archive.put_scalar(prefix + "stable_dt", stable_dt_);
  archive.put_scalar(prefix + "grid_radius", grid_->radius());
}

void MultiMaterialSolver::restore(const StateArchive& archive, const std::string& prefix) {
  restore_store(store_, archive, prefix);
  time_ = archive.scalar(prefix + "time");
  steps_ = static_cast<std::size_t>(archive.scalar(prefix + "steps"));
  stable_dt_ = archive.scalar(prefix + "stable_dt");
  grid_.emplace(domain_, archive.scalar(prefix + "grid_radius"));
  read_stress_fields();
  if (total_lagrangian_) {
    total_lagrangian_->refer(bonded_particles(), store_.size());
    unload_loosened();
  }
}

}  // namespace partimix::sph
