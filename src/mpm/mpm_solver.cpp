#include "mpm/mpm_solver.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "core/error.hpp"
#include "materials/granular/granular_stress.hpp"
#include "mpm/point_exits.hpp"
#include "mpm/point_feeds.hpp"
#include "mpm/point_fill.hpp"
#include "particles/store_state.hpp"

namespace partimix::mpm {
namespace {

std::unique_ptr<grid::ShapeFunction> make_shape(const MpmConfig& config) {
  double spacing = config.cell_size;
  for (const PointFill& fill : config.fills)
    spacing = std::min(spacing, fill.spacing);
  auto shape = grid::shape_function_registry().create(
      config.shape_function, grid::ShapeFunctionOptions{0.5 * spacing / config.cell_size});
  if (!shape)
    throw std::logic_error("unknown shape function " + config.shape_function);
  return shape;
}

grid::CartesianGrid make_grid(const Domain& domain, const MpmConfig& config) {
  try {
    return grid::CartesianGrid(domain, config.cell_size, config.max_grid_nodes);
  } catch (const InputError& error) {
    throw InputError({"", 0, 0, "mpm.cell_size"}, error.message());
  }
}

// tau = 0.06 sqrt(h / |g|) (docs/mpm.md, "Transfers"); without gravity 0, the filter every step.
double automatic_filter_time(double cell_size, const Vec3& gravity) {
  const double g = gravity.norm();
  return g > 0.0 ? 0.06 * std::sqrt(cell_size / g) : 0.0;
}

}  // namespace

MpmSolver::MpmSolver(ParticleStore& store, const Domain& domain, const MpmConfig& config,
                     const Vec3& gravity, const io::SizeLimits& limits)
    : store_(store),
      domain_(domain),
      config_(config),
      gravity_(gravity),
      fields_(store),
      grid_(make_grid(domain, config)),
      shape_(make_shape(config)),
      boundaries_(grid_, config.walls),
      feeds_(config_.feeds, config_.materials, domain, gravity, limits) {
  fill_points(config_, domain_, gravity_, limits, store_, fields_);
  next_id_ = static_cast<std::int64_t>(store_.size());
  transfer_ = {config_.apic,
               config_.filter_time.value_or(automatic_filter_time(config_.cell_size, gravity_)),
               shape_->apic_inertia()};
  double mean_mass = 0.0;
  for (const double m : store_.mass())
    mean_mass += m;
  mean_mass /= static_cast<double>(std::max<std::size_t>(store_.size(), 1));
  min_node_mass_ = 1e-12 * mean_mass;
  for (const materials::GranularMaterial& material : config_.materials)
    wave_speed_ = std::max(wave_speed_, material.wave_speed());
  nodes_.resize(grid_.node_count());
  for (const Vec3& v : store_.velocity())
    max_speed_ = std::max(max_speed_, v.norm());
}

// dt = cfl h / (c + max |v_p|) (docs/mpm.md, "Time step").
double MpmSolver::stable_dt() const {
  return config_.cfl * config_.cell_size / (wave_speed_ + max_speed_);
}

PointView MpmSolver::view() const {
  return {stencils_, store_.mass(), store_.velocity(), affine_, stress_volume_};
}

// The stencils at the points' positions, the buckets, and the points' affine velocities and
// V sigma as the transfers read them.
void MpmSolver::prepare_points() {
  const std::size_t n = store_.size();
  stencils_.resize(n);
  affine_.resize(n);
  stress_volume_.resize(n);
  gradient_.resize(n);
  grid_velocity_.resize(n);
  const std::ptrdiff_t count = static_cast<std::ptrdiff_t>(n);
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t p = 0; p < count; ++p) {
    stencils_[p] = grid::point_stencil(*shape_, grid_, store_.position()[p]);
    affine_[p] = config_.apic ? fields_.affine(p) : Mat3::Zero();
    stress_volume_[p] = fields_.volume.values[p] * fields_.stress(p);
  }
  buckets_.build(grid_, stencils_);
}

// One explicit step (docs/mpm.md): P2G, forces, walls, G2P, (MUSL re-map and walls), the
// velocity gradients (their dilation averaged through the nodes with `dilation: averaged`), the
// stresses, then the positions.
void MpmSolver::step(double dt) {
  prepare_points();
  points_to_grid(grid_, buckets_, view(), gravity_, min_node_mass_, nodes_);
  advance_nodes(buckets_, dt, min_node_mass_, nodes_);
  boundaries_.apply(time_ + dt, buckets_.active_nodes(), nodes_.velocity_new);
  grid_to_points(grid_, stencils_, nodes_, transfer_, dt, store_.velocity(), affine_,
                 grid_velocity_);
  if (config_.musl) {
    momentum_to_grid(grid_, buckets_, view(), min_node_mass_, nodes_);
    boundaries_.apply(time_ + dt, buckets_.active_nodes(), nodes_.velocity_new);
  }
  velocity_gradients(grid_, stencils_, nodes_.velocity_new, gradient_);
  if (config_.averaged_dilation)
    average_dilation(grid_, buckets_, stencils_, store_.mass(), min_node_mass_, nodes_, gradient_);
  update_stresses(dt);
  move_points(dt);
  mass_out_ += remove_exited(config_.exits, store_, exit_order_);
  mass_in_ += feeds_.refill(store_, fields_, next_id_);
  time_ += dt;
  ++steps_;
}

// Volume by exp(dt tr L) (docs/mpm.md, "Density and volume"), density, and the granular
// stress update of each point.
void MpmSolver::update_stresses(double dt) {
  const std::ptrdiff_t count = static_cast<std::ptrdiff_t>(store_.size());
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t p = 0; p < count; ++p) {
    const materials::GranularMaterial& material = config_.materials[fields_.material.values[p]];
    fields_.volume.values[p] *= std::exp(dt * gradient_[p].trace());
    const double density = store_.mass()[p] / fields_.volume.values[p];
    materials::GranularPoint point{fields_.stress(p), fields_.pressure.values[p],
                                   fields_.plastic_strain.values[p],
                                   fields_.inertial_number.values[p]};
    materials::update_granular_stress(material, gradient_[p], dt, density, point);
    fields_.set_stress(p, point.stress);
    fields_.density.values[p] = density;
    fields_.pressure.values[p] = point.pressure;
    fields_.plastic_strain.values[p] = point.plastic_strain;
    fields_.inertial_number.values[p] = point.inertial_number;
    fields_.volumetric_strain.values[p] = std::log(density / material.density);
    if (config_.apic)
      fields_.set_affine(p, affine_[p]);
  }
}

void MpmSolver::move_points(double dt) {
  double fastest = 0.0;
  const std::ptrdiff_t count = static_cast<std::ptrdiff_t>(store_.size());
#pragma omp parallel for schedule(static) reduction(max : fastest)
  for (std::ptrdiff_t p = 0; p < count; ++p) {
    store_.position()[p] += dt * grid_velocity_[p];
    domain_.wrap(store_.position()[p]);
    fastest = std::max(fastest, store_.velocity()[p].norm());
  }
  max_speed_ = fastest;
}

std::map<std::string, double> MpmSolver::derived_parameters() const {
  std::map<std::string, double> parameters{
      {"cell size [m]", config_.cell_size},
      {"grid nodes [-]", static_cast<double>(grid_.node_count())},
      {"elastic wave speed [m/s]", wave_speed_},
      {"time step at rest [s]", config_.cfl * config_.cell_size / wave_speed_},
      {"transfer filter time [s]", transfer_.filter_time},
      {"material points [-]", static_cast<double>(store_.size())}};
  for (const materials::GranularMaterial& material : config_.materials) {
    const std::string prefix = config_.materials.size() > 1 ? material.name + " " : "";
    parameters[prefix + "grain density [kg/m^3]"] = material.grain_density();
    parameters[prefix + "bulk modulus [Pa]"] = material.bulk_modulus();
    parameters[prefix + "shear modulus [Pa]"] = material.shear_modulus();
  }
  return parameters;
}

void MpmSolver::save(StateArchive& archive, const std::string& prefix) const {
  save_store(store_, archive, prefix);
  archive.put_doubles(prefix + "times",
                      std::vector<double>{time_, max_speed_, mass_out_, mass_in_});
  archive.put_integers(prefix + "steps", std::vector<std::int64_t>{steps_, next_id_});
}

void MpmSolver::restore(const StateArchive& archive, const std::string& prefix) {
  restore_store(store_, archive, prefix, !config_.exits.empty() || !config_.feeds.empty());
  const auto materials_count = static_cast<std::int32_t>(config_.materials.size());
  for (const std::int32_t m : fields_.material.values) {
    if (m < 0 || m >= materials_count)
      throw StateError(fmt::format("{}fields/material: a point of material {}, the case has {}",
                                   prefix, m, materials_count));
  }
  const auto times = archive.doubles(prefix + "times");
  const auto steps = archive.integers(prefix + "steps");
  if (times.size() != 4 || steps.size() != 2)
    throw StateError(prefix + ": the times or steps entries have the wrong size");
  time_ = times[0];
  max_speed_ = times[1];
  mass_out_ = times[2];
  mass_in_ = times[3];
  steps_ = steps[0];
  next_id_ = steps[1];
}

}  // namespace partimix::mpm
