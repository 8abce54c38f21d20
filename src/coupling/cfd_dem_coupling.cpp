#include "coupling/cfd_dem_coupling.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "cfd/face_stencil.hpp"
#include "core/error.hpp"
#include "coupling/void_fraction.hpp"

namespace partimix::coupling {
namespace {

double largest_spacing(const grid::StaggeredGrid& grid) {
  double h = 0.0;
  for (int axis = 0; axis < grid.dimensions(); ++axis)
    h = std::max(h, grid.spacing(axis));
  return h;
}

}  // namespace

// V_i and d_i by grain id, from the grains' `volume` field (superquadrics) or their radius
// (spheres); d_i the diameter of the sphere of the grain's volume. The kernel's support b is
// kernel_radius (default 2 d_max), at least 1.5 h_max (docs/cfd-dem.md, "Void fraction").
CfdDemCoupling::CfdDemCoupling(cfd::CfdSolver& fluid, std::size_t fluid_method,
                               dem::DemSolver& grains, std::size_t grain_method,
                               ParticleStore& grain_store, const CfdDemSettings& settings,
                               const Vec3& gravity)
    : fluid_(fluid),
      fluid_method_(fluid_method),
      grains_(grains),
      grain_method_(grain_method),
      external_(grains.enable_external_forces()),
      grain_void_fraction_(&grain_store.add_scalar("fluid_void_fraction", "-").values),
      grain_fluid_force_(&grain_store.add_vector("fluid_force", "N").values),
      settings_(settings),
      gravity_(gravity),
      law_(drag_law_registry().create(settings.drag)) {
  const ParticleStore& store = grains.particles();
  const Field<double>* volume = store.find_scalar("volume");
  const Field<double>& radius = *store.find_scalar("radius");
  volumes_.assign(store.size(), 0.0);
  diameters_.assign(store.size(), 0.0);
  double largest = 0.0;
  for (std::size_t p = 0; p < store.size(); ++p) {
    const double r = radius.values[p];
    const double v = volume ? volume->values[p] : 4.0 / 3.0 * std::numbers::pi * r * r * r;
    const auto id = static_cast<std::size_t>(store.id()[p]);
    volumes_[id] = v;
    diameters_[id] = std::cbrt(6.0 * v / std::numbers::pi);
    largest = std::max(largest, diameters_[id]);
  }
  radius_ = std::max(settings.kernel_radius.value_or(2.0 * largest),
                     1.5 * largest_spacing(fluid.fluid().grid()));
}

void CfdDemCoupling::before_method(std::size_t m, double time, double dt) {
  if (m == fluid_method_)
    exchange_with_fluid(time, dt);
  else if (m == grain_method_)
    exchange_with_grains(dt);
}

// At the run's start the fluid starts with the grains' void fraction (no change over its first
// step).
void CfdDemCoupling::exchange_with_fluid(double time, double dt) {
  frame_ = fluid_.frame().pose(time);
  deferred_.assign(grains_.particles().size(), Vec3::Zero());
  if (started_)
    follow_grains(last_dt_);
  if (started_ && settings_.two_way)
    settle_last_step(last_dt_);
  map_grains();
  if (settings_.two_way && started_)
    fluid_.fluid().set_void_fraction(void_fraction_);
  else if (settings_.two_way)
    fluid_.fluid().start_void_fraction(void_fraction_);
  set_drag();
  if (settings_.two_way)
    set_fluid_source(dt);
  started_ = true;
  last_dt_ = dt;
}

void CfdDemCoupling::exchange_with_grains(double dt) {
  pressure_gradients();
  set_grain_forces(dt);
}

// (∇p)_f on the open faces from the fluid's present pressure.
void CfdDemCoupling::pressure_gradients() {
  const cfd::FluidSolver& fluid = fluid_.fluid();
  const grid::StaggeredGrid& grid = fluid.grid();
  for (int a = 0; a < grid.dimensions(); ++a) {
    gradient_[a].assign(grid.face_count(a), 0.0);
    grid.for_each_face(a, [&](const cfd::Coordinates& f, std::size_t index) {
      if (fluid.mask().open_face[a][index])
        gradient_[a][index] = cfd::gradient_across(grid, a, f, fluid.pressure());
    });
  }
}

// The fluid at grain p with its weights of the last mapping; its pressure gradient from the
// face gradients found before the grains step; both in the lab.
CfdDemCoupling::Sample CfdDemCoupling::sample(std::size_t p, bool with_pressure) const {
  const cfd::FluidSolver& fluid = fluid_.fluid();
  Sample s;
  const auto cells = cell_weights_.of(p);
  if (cells.empty()) {
    s.mapped = false;
    return s;
  }
  s.void_fraction = 0.0;
  s.viscosity = 0.0;
  s.density = 0.0;
  for (const KernelWeights::Weight& w : cells) {
    s.void_fraction += w.weight * void_fraction_[w.cell];
    s.viscosity += w.weight * fluid.viscosity()[w.cell];
    s.density += w.weight * fluid.density()[w.cell];
  }
  for (int a = 0; a < fluid.grid().dimensions(); ++a)
    for (const FaceWeights::Weight& w : face_weights_.of(a, p)) {
      s.velocity[a] += w.weight * fluid.velocity()[a][w.face];
      if (with_pressure)
        s.pressure_gradient[a] += w.weight * gradient_[a][w.face];
    }
  s.velocity = cfd::lab_velocity(frame_, frame_positions_[p], s.velocity);
  s.pressure_gradient = frame_.rotation * s.pressure_gradient;
  return s;
}

// Each grain's row of the last step by its id (the DEM sorts its grains), the fluid's velocity
// it stepped with, and its acceleration (v_i - v_i^{n-1}) / Δt over the step.
void CfdDemCoupling::follow_grains(double dt) {
  const ParticleStore& store = grains_.particles();
  row_of_id_.resize(ids_.size());
  for (std::size_t r = 0; r < ids_.size(); ++r)
    row_of_id_[static_cast<std::size_t>(ids_[r])] = r;
  previous_fluid_velocities_.resize(store.size());
  accelerations_.resize(store.size());
  for (std::size_t p = 0; p < store.size(); ++p) {
    const std::size_t r = row_of_id_[static_cast<std::size_t>(store.id()[p])];
    previous_fluid_velocities_[p] = fluid_velocities_[r];
    accelerations_[p] = (store.velocity()[p] - velocities_[r]) / dt;
  }
}

// D_i = J_i - Δt (K_i (u_i - v_i) + f_i) for each grain of the last step (rows by id: the DEM
// sorts its grains), u_i the fluid's velocity the grain stepped with, v_i its velocity the
// fluid's step used, f_i the held force other than the drag: the impulse the grain received less
// what the fluid's step gave it (docs/cfd-dem.md, "Momentum"). With `gradient` f_i = -V_i ∇p^{n+1}
// is what the fluid's step carried as -ε ∇p^{n+1}, gathered with the same weights; the virtual
// mass, which the fluid's step did not carry, stays in D_i and the fluid gives it over the next
// step. Rows as follow_grains() found them.
void CfdDemCoupling::settle_last_step(double dt) {
  const ParticleStore& store = grains_.particles();
  for (std::size_t p = 0; p < store.size(); ++p) {
    const std::size_t r = row_of_id_[static_cast<std::size_t>(store.id()[p])];
    const Vec3 drag = drag_[r] * (fluid_velocities_[r] - velocities_[r]);
    deferred_[p] = (*external_.impulse)[p] - dt * (drag + pressure_force_[r]);
  }
}

// The weights and void fraction of the grains where they are now, in the fluid's frame.
void CfdDemCoupling::map_grains() {
  const ParticleStore& store = grains_.particles();
  const cfd::FluidSolver& fluid = fluid_.fluid();
  row_volumes_.resize(store.size());
  row_radii_.resize(store.size());
  frame_positions_.resize(store.size());
  const Mat3 back = frame_.rotation.transpose();
  for (std::size_t p = 0; p < store.size(); ++p) {
    const auto id = static_cast<std::size_t>(store.id()[p]);
    row_volumes_[p] = volumes_[id];
    row_radii_[p] = 0.5 * diameters_[id];
    frame_positions_[p] = frame_.start_origin + back * (store.position()[p] - frame_.origin);
  }
  if (settings_.divided)
    cell_weights_.build_divided(fluid.grid(), fluid.mask(), frame_positions_, row_radii_);
  else
    cell_weights_.build(fluid.grid(), fluid.mask(), frame_positions_, radius_);
  face_weights_.build(fluid.grid(), fluid.mask(), cell_weights_, store.size());
  clipped_ = void_fraction(fluid.grid(), cell_weights_, row_volumes_, settings_.min_void_fraction,
                           void_fraction_);
}

// K_i from the law with the fluid's present velocity and the grains' v_i (docs/cfd-dem.md,
// "The forces on a grain").
void CfdDemCoupling::set_drag() {
  const ParticleStore& store = grains_.particles();
  drag_.assign(store.size(), 0.0);
  velocities_.assign(store.velocity().begin(), store.velocity().end());
  for (std::size_t p = 0; p < store.size(); ++p) {
    const auto id = static_cast<std::size_t>(store.id()[p]);
    const Sample s = sample(p, false);
    if (!s.mapped)
      continue;
    const Vec3 slip = s.velocity - store.velocity()[p];
    const DragState state{s.void_fraction, slip.norm(), diameters_[id], s.density, s.viscosity};
    drag_[p] = law_->coefficient(state) * volumes_[id];
  }
}

// F_i = K_i u_i + the pressure's or buoyancy's force, u_i and ∇p from the fluid's new state,
// held for the grains' sub-steps, which take the drag backward in time, so that their length may
// exceed the grain's relaxation time m_i / K_i. In a rotating frame u_i's part Ω × (x_i - a) is
// left to the DEM, which takes it at the grain's place in each sub-step
// (dem/external_forces.hpp). The frames' fields get ε_i and the force K_i (u_i - v_i) + the
// others as set.
void CfdDemCoupling::set_grain_forces(double dt) {
  const ParticleStore& store = grains_.particles();
  ids_.assign(store.id().begin(), store.id().end());
  fluid_velocities_.assign(store.size(), Vec3::Zero());
  other_force_.assign(store.size(), Vec3::Zero());
  pressure_force_.assign(store.size(), Vec3::Zero());
  grains_.set_external_rotation(frame_.angular_velocity, frame_.origin);
  for (std::size_t p = 0; p < store.size(); ++p) {
    const auto id = static_cast<std::size_t>(store.id()[p]);
    const Sample s = sample(p, true);
    if (s.mapped) {
      fluid_velocities_[p] = s.velocity;
      if (settings_.pressure_force == PressureForce::gradient)
        pressure_force_[p] = -volumes_[id] * s.pressure_gradient;
      else if (settings_.pressure_force == PressureForce::buoyancy)
        pressure_force_[p] = -s.density * volumes_[id] * gravity_;
      other_force_[p] = pressure_force_[p] + virtual_mass(p, id, s, dt);
    }
    const Vec3 turning = frame_.velocity_at(store.position()[p]);
    (*external_.force)[p] = drag_[p] * (fluid_velocities_[p] - turning) + other_force_[p];
    (*external_.drag)[p] = drag_[p];
    (*external_.impulse)[p] = Vec3::Zero();
    (*grain_void_fraction_)[p] = s.void_fraction;
    (*grain_fluid_force_)[p] =
        drag_[p] * (fluid_velocities_[p] - store.velocity()[p]) + other_force_[p];
  }
}

// C_vm ρ_i V_i ((u_i^{n+1} - u_i^n) / Δt - a_i), the relative acceleration along the grain's path
// over the last step (seed 004's F_x; docs/cfd-dem.md, "The forces on a grain"); none in the first
// step.
Vec3 CfdDemCoupling::virtual_mass(std::size_t p, std::size_t id, const Sample& s, double dt) const {
  if (!settings_.virtual_mass || accelerations_.empty())
    return Vec3::Zero();
  const double mass = settings_.virtual_mass_coefficient * s.density * volumes_[id];
  return mass * ((s.velocity - previous_fluid_velocities_[p]) / dt - accelerations_[p]);
}

// K_f = Σ_i w_if K_i / V_f and S_e,f = Σ_i w_if (K_i v_i - D_i / Δt) / V_f, in the fluid's
// frame: v_i relative to it and D_i turned into its directions.
void CfdDemCoupling::set_fluid_source(double dt) {
  cfd::FluidSolver& fluid = fluid_.fluid();
  const double volume = fluid.grid().cell_volume();
  const Mat3 back = frame_.rotation.transpose();
  pushes_.resize(drag_.size());
  for (std::size_t p = 0; p < drag_.size(); ++p)
    pushes_[p] = drag_[p] * relative_velocity(p) - back * deferred_[p] / dt;
  for (int a = 0; a < fluid.grid().dimensions(); ++a) {
    std::vector<double>& k = fluid.drag_coefficient()[a];
    std::vector<double>& source = fluid.grain_source()[a];
    std::fill(k.begin(), k.end(), 0.0);
    std::fill(source.begin(), source.end(), 0.0);
    for (std::size_t p = 0; p < drag_.size(); ++p) {
      const double push = pushes_[p][a];
      for (const FaceWeights::Weight& w : face_weights_.of(a, p)) {
        k[w.face] += w.weight * drag_[p] / volume;
        source[w.face] += w.weight * push / volume;
      }
    }
  }
}

// Rᵀ (v_i - Ω × (x_i - a)) with the grain's velocity as the fluid's step uses it.
Vec3 CfdDemCoupling::relative_velocity(std::size_t p) const {
  const Vec3 lab_place = frame_.place(frame_positions_[p]);
  return frame_.rotation.transpose() * (velocities_[p] - frame_.velocity_at(lab_place));
}

Vec3 CfdDemCoupling::deferred_momentum() const {
  Vec3 sum = Vec3::Zero();
  for (const Vec3& d : deferred_)
    sum += d;
  return sum;
}

void CfdDemCoupling::save(StateArchive& archive, const std::string& prefix) const {
  archive.put_doubles(prefix + "times", std::vector<double>{started_ ? 1.0 : 0.0, last_dt_});
  archive.put_integers(prefix + "ids", ids_);
  archive.put_doubles(prefix + "drag", drag_);
  archive.put_vectors(prefix + "velocities", velocities_);
  archive.put_vectors(prefix + "fluid_velocities", fluid_velocities_);
  archive.put_vectors(prefix + "other_force", other_force_);
  archive.put_vectors(prefix + "pressure_force", pressure_force_);
}

// What the last step used of each grain, by the grains' order when it began (ids).
void CfdDemCoupling::restore(const StateArchive& archive, const std::string& prefix) {
  const auto times = archive.doubles(prefix + "times");
  if (times.size() != 2)
    throw StateError(prefix + "times: the wrong size");
  started_ = times[0] != 0.0;
  last_dt_ = times[1];
  const auto ids = archive.integers(prefix + "ids");
  ids_.assign(ids.begin(), ids.end());
  const auto drag = archive.doubles(prefix + "drag");
  drag_.assign(drag.begin(), drag.end());
  velocities_ = archive.vectors(prefix + "velocities");
  fluid_velocities_ = archive.vectors(prefix + "fluid_velocities");
  other_force_ = archive.vectors(prefix + "other_force");
  pressure_force_ = archive.vectors(prefix + "pressure_force");
  const std::size_t n = grains_.particles().size();
  const bool fits = ids_.size() == n && drag_.size() == n && velocities_.size() == n &&
                    fluid_velocities_.size() == n && other_force_.size() == n &&
                    pressure_force_.size() == n;
  if (!fits || std::any_of(ids_.begin(), ids_.end(), [n](std::int64_t id) {
        return id < 0 || static_cast<std::size_t>(id) >= n;
      }))
    throw StateError(fmt::format("{}: the rows do not fit the run's {} grains", prefix, n));
}

}  // namespace partimix::coupling
