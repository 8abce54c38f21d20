#include "sph/sph_solver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <spdlog/spdlog.h>

#include "core/error.hpp"
#include "particles/store_state.hpp"
#include "sph/eos/incompressible_eos.hpp"
#include "sph/fluid_rates.hpp"
#include "sph/particle_shifting.hpp"
#include "sph/shear_rate.hpp"
#include "sph/shepard_filter.hpp"
#include "sph/sound_speed.hpp"
#include "sph/viscous_stress.hpp"
#include "sph/wall_forces.hpp"
#include "sph/wall_state.hpp"

namespace partimix::sph {
namespace {

// Skin of the neighbour list as a fraction of the kernel support: a larger skin rebuilds less
// often but lists more partners beyond the support, each costing a distance test
// (docs/performance.md, "DualSPHysics' CaseDambreak, side by side").
constexpr double kNeighbourSkin = 0.1;

// With sph.smoothing_length: variable the neighbour search starts at this many reference
// supports, widens to 1.1 times the largest h_i's support when that outgrows it, and stops the
// run beyond kLargestReach (docs/sph.md, "Variable smoothing length").
constexpr double kVariableReach = 1.05;
constexpr double kWidening = 1.1;
constexpr double kLargestReach = 4.0;

double search_reach(const Config& config) {
  return config.variable_smoothing_length ? kVariableReach : 1.0;
}

std::unique_ptr<Kernel> make_kernel(const std::string& name, const std::string& key) {
  auto kernel = kernel_registry().create(name);
  if (!kernel)
    throw InputError(InputLocation{"", 0, 0, key}, "unknown kernel '" + name + "'");
  return kernel;
}

DensityDiffusion diffusion_from(const std::string& name) {
  if (name == "none")
    return DensityDiffusion::none;
  if (name == "molteni")
    return DensityDiffusion::molteni;
  if (name == "fourtakas")
    return DensityDiffusion::fourtakas;
  throw InputError(InputLocation{"", 0, 0, "sph.density.diffusion"},
                   "unknown model '" + name + "'");
}

// `auto`: the Morris term for a Newtonian fluid (the same answer as the stress form, at less
// cost), the stress form where the viscosity varies (docs/sph.md, "Viscous operators"); with
// implicit viscosity the stress form's div(eta G^T) is the explicit part of the step.
ViscousOperator viscous_operator_from(const Config& config, const FluidProperties& fluid) {
  if (!config.laminar_viscosity)
    return ViscousOperator::none;
  if (config.viscous_operator == "auto") {
    return fluid.rheology.model == "newtonian" ? ViscousOperator::morris : ViscousOperator::stress;
  }
  if (config.viscous_operator == "morris")
    return ViscousOperator::morris;
  if (config.viscous_operator == "stress")
    return ViscousOperator::stress;
  throw InputError(InputLocation{"", 0, 0, "sph.viscous_operator"},
                   "unknown operator '" + config.viscous_operator + "'");
}

Vec3 without_periodic_axes(const Vec3& gravity, const Domain& domain) {
  Vec3 g = gravity;
  for (int axis = 0; axis < 3; ++axis) {
    if (domain.periodic[axis])
      g[axis] = 0.0;
  }
  return g;
}

Parameters make_parameters(const Config& config, const FluidProperties& fluid, const Vec3& gravity,
                           const Domain& domain, const ParticleStore& store) {
  Parameters p;
  p.dimensions = domain.dimensions;
  p.spacing = config.spacing;
  p.h = config.smoothing_length();
  p.eta2 = 0.01 * p.h * p.h;
  p.reference_density = fluid.density;
  p.gravity = gravity;
  p.hydrostatic_gravity = without_periodic_axes(gravity, domain);
  p.sound_speed =
      resolve_sound_speed(config, store, p.hydrostatic_gravity,
                          materials::BoundedRheology(fluid.rheology), fluid.density, p.dimensions);
  p.viscous_operator = viscous_operator_from(config, fluid);
  p.harmonic_viscosity_mean = config.viscosity_mean == "harmonic";
  p.artificial_viscosity = config.artificial_viscosity;
  p.diffusion = diffusion_from(config.density.diffusion);
  p.delta = config.density.delta;
  // The incompressible scheme's wall rows are not floored, so neither are its loads' wall
  // pressures (docs/sph.md, "Walls").
  p.negative_wall_pressure = config.negative_wall_pressure || config.scheme == "incompressible";
  p.extrapolated_wall_velocity = config.wall_velocity == "extrapolated";
  return p;
}

// The incompressible scheme keeps the density at rho0 (docs/sph.md, "Incompressible SPH").
std::unique_ptr<EquationOfState> make_equation_of_state(const Config& config,
                                                        const FluidProperties& fluid,
                                                        double sound_speed) {
  if (config.scheme == "incompressible")
    return std::make_unique<IncompressibleEos>(fluid.density);
  return equation_of_state_registry().create(
      config.equation_of_state, EosParameters{fluid.density, sound_speed, config.tait_gamma});
}

}  // namespace

SphSolver::SphSolver(ParticleStore& store, const Domain& domain, const Config& config,
                     const FluidProperties& fluid, const Vec3& gravity,
                     geometry::MovingBodies* bodies)
    : store_(store),
      domain_(domain),
      config_(config),
      parameters_(make_parameters(config, fluid, gravity, domain, store)),
      fields_(store),
      kernel_(make_kernel(config.kernel, "sph.kernel")),
      gradient_kernel_(
          make_kernel(config.gradient_kernel.empty() ? config.kernel : config.gradient_kernel,
                      "sph.gradient_kernel")),
      eos_(make_equation_of_state(config, fluid, parameters_.sound_speed)),
      kernel_table_(*kernel_, parameters_.h, domain.dimensions),
      gradient_table_(*gradient_kernel_, parameters_.h, domain.dimensions),
      grid_(domain, search_reach(config) *
                        std::max(kernel_table_.support_radius(), gradient_table_.support_radius())),
      neighbours_(domain, search_reach(config) * gradient_table_.support_radius(),
                  kNeighbourSkin * gradient_table_.support_radius()),
      bodies_(bodies),
      rheology_(fluid.rheology),
      newtonian_(fluid.rheology.model == "newtonian") {
  if (!eos_) {
    throw InputError(InputLocation{"", 0, 0, "sph.equation_of_state"},
                     "unknown equation of state '" + config.equation_of_state + "'");
  }
  if (parameters_.viscous_operator == ViscousOperator::stress)
    fields_.viscous_stress.resize(store_.size(), Mat3::Zero());
  if (config.variable_smoothing_length) {
    // Wall particles keep the reference h and scale 1; sorting keeps them after the fluid.
    smoothing_length_ = &store_.add_scalar("smoothing_length", "m").values;
    std::fill(smoothing_length_->begin(), smoothing_length_->end(), parameters_.h);
    fields_.kernel_scale.assign(store_.size(), 1.0);
    fields_.gradient_scale.assign(store_.size(), 1.0);
  }
  reach_ = search_reach(config);
  if (bodies_ != nullptr && bodies_->count() > 0) {
    body_force_ = &store_.add_vector("body_force", "N", false).values;
    body_couple_ = &store_.add_vector("body_couple", "N m", false).values;
  }
  if (config.viscosity_integration == "implicit") {
    if (config.scheme != "incompressible") {
      throw InputError(InputLocation{"", 0, 0, "sph.viscosity_integration"},
                       "implicit viscosity needs sph.scheme: incompressible (the "
                       "weakly-compressible step is bound by the sound speed anyway)");
    }
    viscous_.emplace(config.pressure_tolerance, config.pressure_iterations);
  }
  if (config.scheme == "incompressible") {
    poisson_.emplace(config.pressure_tolerance, config.pressure_iterations);
    flow_speed_estimate_ = estimated_max_velocity(config, store, parameters_.hydrostatic_gravity);
    parameters_.diffusion = DensityDiffusion::none;
  }
  initialise_fluid();
  fluid_count_ = static_cast<std::size_t>(std::count_if(
      fields_.kind.begin(), fields_.kind.end(), [](std::int32_t k) { return is_fluid(k); }));
  move_bodies(0.0);
  sort_by_cell();
  if (poisson_)
    refresh_incompressible();
  else
    interact();
  initial_dt_ = stable_dt();
}

// The grid and the rate-evaluation state are those of the end of the last step (or of the
// constructor), so the forces belong to the current positions. The traction on a wall is
// tau . n with tau = eta (G + G^T); the Morris term carries only the eta G part to the walls, so
// with it the loads add the eta G^T part at its exact value on a rigid wall (docs/power.md,
// "Viscous traction").
void SphSolver::update_body_forces() {
  if (body_force_ == nullptr)
    return;
  const WallTraction traction = parameters_.viscous_operator == ViscousOperator::morris
                                    ? WallTraction::rigid_wall
                                    : WallTraction::dynamics;
  compute_wall_forces(fields_, fluid_count_, grid_, gradient_table_, parameters_, traction,
                      {*body_force_, *body_couple_});
}

void SphSolver::initialise_fluid() {
  const double volume = std::pow(parameters_.spacing, domain_.dimensions);
  const Vec3& g = parameters_.hydrostatic_gravity;
  const double g_norm = g.norm();
  double top = std::numeric_limits<double>::lowest();
  for (std::size_t i = 0; i < store_.size(); ++i) {
    if (store_.is_fluid(i) && g_norm > 0.0) {
      top = std::max(top, -g.dot(fields_.position[i]) / g_norm);
    }
  }
  top += 0.5 * parameters_.spacing;
  for (std::size_t i = 0; i < store_.size(); ++i) {
    fields_.mass[i] = parameters_.reference_density * volume;
    fields_.density[i] = parameters_.reference_density;
    if (store_.is_fluid(i) && g_norm > 0.0) {
      const double depth = top + g.dot(fields_.position[i]) / g_norm;
      fields_.density[i] = eos_->density(parameters_.reference_density * g_norm * depth);
    }
  }
  wrap_positions();
}

void SphSolver::move_bodies(double time) {
  if (bodies_ != nullptr)
    bodies_->move_to(time);
}

void SphSolver::wrap_positions() {
  for (auto& x : fields_.position)
    domain_.wrap(x);
}

// Orders the store by kind, then by cell: fluid particles take [0, fluid_count_) and, as the
// grid's counting sort keeps index order within a cell, come before walls in every cell.
void SphSolver::sort_by_cell() {
  grid_.build(fields_.position);
  sort_order_.resize(store_.size());
  std::size_t next_fluid = 0;
  std::size_t next_wall = fluid_count_;
  for (const std::uint32_t i : grid_.cell_order()) {
    sort_order_[store_.is_fluid(i) ? next_fluid++ : next_wall++] = i;
  }
  store_.reorder(sort_order_);
  neighbours_.invalidate();
}

// h_i = eta (m_i / rho_i)^(1/d) of each fluid particle and its kernel's scales to the reference
// h's table (docs/sph.md, "Variable smoothing length"): with s = h / h_i, s^d = (h / eta)^d rho_i
// / m_i, so one root gives s, h_i and s^(d+1). The search widens for a particle beyond its reach.
void SphSolver::update_smoothing_lengths() {
  if (smoothing_length_ == nullptr)
    return;
  const double h = parameters_.h;
  const double inverse_dimensions = 1.0 / domain_.dimensions;
  const double reference_volume = std::pow(h / config_.smoothing_ratio, domain_.dimensions);
  const auto n = static_cast<std::ptrdiff_t>(fluid_count_);
  double smallest = h;
  double largest = h;
#pragma omp parallel for schedule(static) reduction(min : smallest) reduction(max : largest)
  for (std::ptrdiff_t ii = 0; ii < n; ++ii) {
    const auto i = static_cast<std::size_t>(ii);
    const double scale_d = reference_volume * fields_.density[i] / fields_.mass[i];
    const double scale = std::pow(scale_d, inverse_dimensions);
    const double h_i = h / scale;
    (*smoothing_length_)[i] = h_i;
    fields_.kernel_scale[i] = scale;
    fields_.gradient_scale[i] = scale_d * scale;
    smallest = std::min(smallest, h_i);
    largest = std::isnan(h_i) ? std::numeric_limits<double>::infinity() : std::max(largest, h_i);
  }
  smallest_smoothing_length_ = smallest;
  if (largest > reach_ * h)
    widen_search(largest);
}

// A new grid and neighbour list reaching kWidening times the support of the largest h (a rare
// event: the hot loop's buffers are sized anew once).
void SphSolver::widen_search(double largest_h) {
  const double h = parameters_.h;
  if (!(largest_h <= kLargestReach * h)) {
    throw RunError(fmt::format(
        "at t = {:.6g} s a fluid particle's variable smoothing length reached {:.4g} m, more than "
        "{} times h = {:.4g} m (with equal masses, a density below rho0 / {}^d)",
        time_, largest_h, kLargestReach, h, kLargestReach));
  }
  reach_ = std::min(kWidening * largest_h / h, kLargestReach);
  const double support = gradient_table_.support_radius();
  try {
    grid_ = CellGrid(domain_, reach_ * std::max(kernel_table_.support_radius(), support));
    neighbours_ = NeighbourList(domain_, reach_ * support, kNeighbourSkin * support);
  } catch (const InputError& error) {
    throw RunError(fmt::format(
        "at t = {:.6g} s the variable smoothing length reached {:.4g} m, whose neighbour search "
        "no longer fits the domain: {}",
        time_, largest_h, error.message()));
  }
  grid_.build(fields_.position);
}

void SphSolver::interact() {
  update_smoothing_lengths();
  grid_.build(fields_.position);
  for (std::size_t i = 0; i < fluid_count_; ++i) {
    fields_.pressure[i] = eos_->pressure(fields_.density[i]);
  }
  update_wall_state(fields_, fluid_count_, grid_, kernel_table_, *eos_, parameters_);
  update_viscosity();
  const RateExtremes extremes = fluid_rates();
  max_acceleration_ = extremes.max_acceleration;
  max_speed_ = extremes.max_speed;
}

RateExtremes SphSolver::fluid_rates() {
  neighbours_.update(fields_.position, fluid_count_, fluid_count_);
  return compute_fluid_rates(fields_, fluid_count_, neighbours_, gradient_table_, parameters_,
                             rate_buffers_);
}

// Apparent viscosity of each fluid particle from its shear rate (docs/rheology.md), and the
// viscous stresses for the stress form; with the Morris form a Newtonian fluid skips the shear
// rates.
void SphSolver::update_viscosity() {
  if (parameters_.viscous_operator == ViscousOperator::stress) {
    max_viscosity_ =
        compute_viscous_stress(fields_, fluid_count_, grid_, gradient_table_, kernel_table_,
                               rheology_, domain_.dimensions, config_.corrected_velocity_gradient);
    return;
  }
  if (newtonian_ && steps_ > 0)
    return;  // constant, filled during the first step
  if (!newtonian_) {
    compute_shear_rates(fields_, fluid_count_, grid_, gradient_table_, domain_.dimensions,
                        config_.corrected_velocity_gradient);
  }
  double largest = 0.0;
  for (std::size_t i = 0; i < fluid_count_; ++i) {
    fields_.viscosity[i] = rheology_.viscosity(fields_.shear_rate[i]);
    largest = std::max(largest, fields_.viscosity[i]);
  }
  max_viscosity_ = largest;
}

double SphSolver::stable_dt() const {
  const TimeStepFactors& factors = config_.time_step;
  const double h = smoothing_length_ != nullptr ? smallest_smoothing_length_ : parameters_.h;
  double dt = poisson_ ? factors.flow_cfl * h / std::max(max_speed_, flow_speed_estimate_)
                       : factors.cfl * h / (parameters_.sound_speed + max_speed_);
  const double nu = max_viscosity_ / parameters_.reference_density;
  if (parameters_.viscous_operator != ViscousOperator::none && nu > 0.0 && !viscous_) {
    dt = std::min(dt, factors.viscous * h * h / nu);
  }
  if (max_acceleration_ > 0.0) {
    dt = std::min(dt, factors.force * std::sqrt(h / max_acceleration_));
  }
  return dt;
}

// Symplectic position-Verlet (docs/sph.md, "Time integration"), half step.
void SphSolver::predict(double dt) {
  start_position_.resize(fluid_count_);
  start_velocity_.resize(fluid_count_);
  start_density_.resize(fluid_count_);
  const auto n = static_cast<std::ptrdiff_t>(fluid_count_);
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t ii = 0; ii < n; ++ii) {
    const auto i = static_cast<std::size_t>(ii);
    start_position_[i] = fields_.position[i];
    start_velocity_[i] = fields_.velocity[i];
    start_density_[i] = fields_.density[i];
    fields_.density[i] += 0.5 * dt * fields_.density_rate[i];
    fields_.velocity[i] += 0.5 * dt * fields_.acceleration[i];
    fields_.position[i] += 0.5 * dt * start_velocity_[i];
  }
  wrap_positions();
}

// Corrector: full step from the start state with the rates at the half step; the density
// update rho^{n+1} = rho^n (2 - eps) / (2 + eps), eps = -(drho/dt / rho)^{n+1/2} dt.
void SphSolver::correct(double dt) {
  const auto n = static_cast<std::ptrdiff_t>(fluid_count_);
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t ii = 0; ii < n; ++ii) {
    const auto i = static_cast<std::size_t>(ii);
    const double epsilon = -fields_.density_rate[i] / fields_.density[i] * dt;
    fields_.velocity[i] = start_velocity_[i] + dt * fields_.acceleration[i];
    fields_.position[i] += 0.5 * dt * fields_.velocity[i];
    fields_.density[i] = start_density_[i] * (2.0 - epsilon) / (2.0 + epsilon);
  }
  wrap_positions();
}

// Moving walls are placed at the instant of each rate evaluation: t + dt/2 for the predictor's
// rates, t + dt for the end of the step.
void SphSolver::advance_weakly_compressible(double dt) {
  predict(dt);
  move_bodies(time_ + 0.5 * dt);
  interact();
  correct(dt);
}

// The projection step (docs/sph.md, "Incompressible SPH"): the viscous prediction at x^n, with
// the wall state of the end of the last step, explicit or implicit; then the pressure solve and
// the projection at x*.
void SphSolver::advance_incompressible(double dt) {
  start_position_.assign(fields_.position.begin(),
                         fields_.position.begin() + static_cast<std::ptrdiff_t>(fluid_count_));
  start_velocity_.assign(fields_.velocity.begin(),
                         fields_.velocity.begin() + static_cast<std::ptrdiff_t>(fluid_count_));
  if (viscous_)
    predict_viscous_implicit(dt);
  else
    predict_viscous_explicit(dt);
  for (std::size_t i = 0; i < fluid_count_; ++i)
    fields_.position[i] += dt * fields_.velocity[i];
  wrap_positions();
  move_bodies(time_ + dt);
  grid_.build(fields_.position);
  stop_unless_converged(poisson_->solve(fields_, fluid_count_, grid_, kernel_table_,
                                        gradient_table_, parameters_, dt),
                        "the pressure Poisson equation");
  project_velocities(fields_, fluid_count_, grid_, gradient_table_, parameters_, dt);
  for (std::size_t i = 0; i < fluid_count_; ++i) {
    fields_.acceleration[i] = (fields_.velocity[i] - start_velocity_[i]) / dt;
    fields_.position[i] =
        start_position_[i] + 0.5 * dt * (start_velocity_[i] + fields_.velocity[i]);
  }
  wrap_positions();
}

// A failed solve stops the run with its residual (docs/sph.md, "Incompressible SPH").
void SphSolver::stop_unless_converged(const LinearSolve& solve, std::string_view what) const {
  if (solve.converged)
    return;
  throw RunError(fmt::format(
      "{} did not converge at t = {:.6g} s: relative residual {:.3g} after {} iterations "
      "(sph.pressure_tolerance {:.3g}, sph.pressure_iterations {})",
      what, time_, solve.residual, solve.iterations, config_.pressure_tolerance,
      config_.pressure_iterations));
}

// u* = u^n + dt (a_visc + g), the rates at x^n without pressure; the last step's pressures are
// kept as the pressure solve's first guess.
void SphSolver::predict_viscous_explicit(double dt) {
  scratch_.assign(fields_.pressure.begin(), fields_.pressure.end());
  std::fill(fields_.pressure.begin(), fields_.pressure.end(), 0.0);
  fluid_rates();
  std::copy(scratch_.begin(), scratch_.end(), fields_.pressure.begin());
  for (std::size_t i = 0; i < fluid_count_; ++i)
    fields_.velocity[i] += dt * fields_.acceleration[i];
}

// Backward Euler (docs/sph.md, "Implicit viscosity"), with Picard iteration on the apparent
// viscosity of a non-Newtonian fluid until no particle's changes by more than 1%; the first time
// that takes more than sph.viscosity_iterations solves, the run says so and goes on. With one
// solve allowed the viscosities are those of the end of the last step (refresh_incompressible).
// The stress form's div(eta G^T) is explicit, from the stresses of the last iterate.
void SphSolver::predict_viscous_implicit(double dt) {
  viscous_->gather_pairs(fields_, fluid_count_, grid_, kernel_table_, gradient_table_, parameters_);
  const bool stress = parameters_.viscous_operator == ViscousOperator::stress;
  for (int iteration = 0; iteration < config_.viscosity_iterations; ++iteration) {
    if (stress)
      compute_stress_divergence(fields_, fluid_count_, grid_, gradient_table_, stress_rates_);
    stop_unless_converged(
        viscous_->solve(fields_, fluid_count_, parameters_, start_velocity_,
                        stress ? std::span<const Vec3>(stress_rates_) : std::span<const Vec3>(),
                        dt),
        "the implicit viscosity solve");
    if (newtonian_ || config_.viscosity_iterations == 1 || !update_apparent_viscosity())
      return;
  }
  if (config_.viscosity_iterations > 1 && !warned_about_picard_) {
    warned_about_picard_ = true;
    spdlog::warn(
        "at t = {:.6g} s the apparent viscosity still changed by more than 1% after "
        "sph.viscosity_iterations = {} solves; the step goes on with the last one (this is said "
        "once)",
        time_, config_.viscosity_iterations);
  }
}

// Apparent viscosities (and, stress form, stresses) from the current velocities; true when one
// changed by more than 1%.
bool SphSolver::update_apparent_viscosity() {
  previous_viscosity_.assign(fields_.viscosity.begin(),
                             fields_.viscosity.begin() + static_cast<std::ptrdiff_t>(fluid_count_));
  update_viscosity();
  bool changed = false;
  for (std::size_t i = 0; i < fluid_count_; ++i)
    changed = changed || std::abs(fields_.viscosity[i] - previous_viscosity_[i]) >
                             0.01 * previous_viscosity_[i];
  return changed;
}

// The state at the end of an incompressible step: wall ghost velocities and pressures, apparent
// viscosities, the extremes of the time step. The force limit sees gravity alone: the pressure
// acts through the projection, the viscous term is bound by its own limit or implicit, and the
// velocity change of a step, which also holds the projection's correction of the particles'
// disorder, held the vessel's step to a quarter of the flow-speed one (docs/sph.md).
void SphSolver::refresh_incompressible() {
  grid_.build(fields_.position);
  update_wall_state(fields_, fluid_count_, grid_, kernel_table_, *eos_, parameters_);
  update_viscosity();
  double max_speed2 = 0.0;
  for (std::size_t i = 0; i < fluid_count_; ++i)
    max_speed2 = std::max(max_speed2, fields_.velocity[i].squaredNorm());
  max_speed_ = std::sqrt(max_speed2);
  max_acceleration_ = parameters_.gravity.norm();
}

void SphSolver::shift_particles_after_step(double dt) {
  grid_.build(fields_.position);
  shift_particles(fields_, fluid_count_, grid_, kernel_table_, parameters_,
                  {config_.shifting.coefficient, max_speed_}, dt, shifting_);
  wrap_positions();
}

void SphSolver::step(double dt) {
  if (poisson_)
    advance_incompressible(dt);
  else
    advance_weakly_compressible(dt);
  ++steps_;
  time_ += dt;
  move_bodies(time_);
  if (config_.shifting.model == "fickian")
    shift_particles_after_step(dt);
  if (config_.density.shepard &&
      steps_ % static_cast<std::size_t>(config_.density.shepard_interval) == 0) {
    grid_.build(fields_.position);
    apply_shepard_filter(fields_, grid_, kernel_table_, scratch_);
  }
  if (steps_ % static_cast<std::size_t>(config_.sort_interval) == 0) {
    sort_by_cell();
  }
  if (poisson_) {
    refresh_incompressible();
    return;
  }
  interact();
  warn_once_if_too_fast();
}

// The Mach criterion c0 >= mach_factor * U_max (docs/sph.md) is checked as the run goes.
void SphSolver::warn_once_if_too_fast() {
  if (warned_about_speed_ || max_speed_ * config_.mach_factor <= parameters_.sound_speed)
    return;
  warned_about_speed_ = true;
  spdlog::warn(
      "the flow reached {:.3g} m/s, above c0 / mach_factor = {:.3g} m/s: density errors grow "
      "beyond 1%; set sph.max_velocity (or sph.sound_speed) higher",
      max_speed_, parameters_.sound_speed / config_.mach_factor);
}

}  // namespace partimix::sph

namespace partimix::sph {

// The store holds every per-particle array the next step reads; the viscous stresses are not
// saved: every interaction recomputes them before use, and analyses sample after a step.
void SphSolver::save(StateArchive& archive, const std::string& prefix) const {
  save_store(store_, archive, prefix);
  archive.put_scalar(prefix + "time", time_);
  archive.put_integers(prefix + "steps",
                       std::vector<std::int64_t>{static_cast<std::int64_t>(steps_)});
  archive.put_doubles(prefix + "time_step_inputs",
                      std::vector<double>{max_acceleration_, max_speed_, max_viscosity_});
  archive.put_integers(prefix + "warned_about_speed",
                       std::vector<std::int64_t>{warned_about_speed_ ? 1 : 0});
  if (poisson_)
    archive.put_scalar(prefix + "pressure_mean_offset", poisson_->mean_offset());
}

void SphSolver::restore(const StateArchive& archive, const std::string& prefix) {
  restore_store(store_, archive, prefix);
  time_ = archive.scalar(prefix + "time");
  steps_ = static_cast<std::size_t>(archive.integers(prefix + "steps").front());
  const auto inputs = archive.doubles(prefix + "time_step_inputs");
  if (inputs.size() != 3)
    throw StateError(prefix + "time_step_inputs: expected 3 values");
  max_acceleration_ = inputs[0];
  max_speed_ = inputs[1];
  max_viscosity_ = inputs[2];
  warned_about_speed_ = archive.integers(prefix + "warned_about_speed").front() != 0;
  update_smoothing_lengths();  // of the restored densities, as at the checkpoint
  // The incompressible step starts from the grid and wall state of the end of the last one,
  // which the constructor built for the case's initial particles: rebuilt for the restored ones
  // (the same values as at the checkpoint, so the resumed run is the uninterrupted one).
  if (poisson_) {
    poisson_->set_mean_offset(archive.scalar(prefix + "pressure_mean_offset"));
    refresh_incompressible();
  }
}

std::map<std::string, double> SphSolver::derived_parameters() const {
  const std::size_t fluid = fluid_count_;
  return {{"smoothing_length [m]", parameters_.h},
          {"sound_speed [m/s]", parameters_.sound_speed},
          {"particle_mass [kg]", fields_.mass.empty() ? 0.0 : fields_.mass.front()},
          {"fluid_particles [-]", static_cast<double>(fluid)},
          {"wall_particles [-]", static_cast<double>(store_.size() - fluid)},
          {"initial_time_step [s]", initial_dt_}};
}

}  // namespace partimix::sph
