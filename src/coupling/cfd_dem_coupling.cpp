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
CfdDemCoupling::CfdDemCoupling(cfd::CfdSolver& fluid, dem::DemSolver& grains,
                               const CfdDemSettings& settings, const Vec3& gravity)
    : fluid_(fluid),
      grains_(grains),
      external_(grains.enable_external_forces()),
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

void CfdDemCoupling::exchange(double /*time*/, double dt) {
  const ParticleStore& store = grains_.particles();
  index_of_id_.resize(store.size());
  for (std::size_t p = 0; p < store.size(); ++p)
    index_of_id_[static_cast<std::size_t>(store.id()[p])] = p;
  pressure_gradients();
  deferred_.assign(store.size(), Vec3::Zero());
  if (started_ && settings_.two_way)
    settle_last_step();
  map_grains();
  set_grain_forces(dt);
  if (settings_.two_way)
    set_fluid_source(dt);
  started_ = true;
  last_dt_ = dt;
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

CfdDemCoupling::Sample CfdDemCoupling::sample(std::size_t row) const {
  const cfd::FluidSolver& fluid = fluid_.fluid();
  Sample s;
  const auto cells = cell_weights_.of(row);
  if (cells.empty()) {
    s.mapped = false;
    return s;
  }
  s.void_fraction = 0.0;
  for (const KernelWeights::Weight& w : cells)
    s.void_fraction += w.weight * void_fraction_[w.cell];
  for (int a = 0; a < fluid.grid().dimensions(); ++a)
    for (const FaceWeights::Weight& w : face_weights_.of(a, row)) {
      s.velocity[a] += w.weight * fluid.velocity()[a][w.face];
      s.pressure_gradient[a] += w.weight * gradient_[a][w.face];
    }
  return s;
}

// D_r = J_r - Δt K_r (u_r^{n+1} - v_r^n) - Δt f_r for each grain r of the last exchange, with
// its weights then: the impulse it received less what the fluid's step gave it (docs/cfd-dem.md,
// "Momentum"): f_r the pressure force at p^{n+1} with `gradient` (the fluid's step carried
// -ε ∇p^{n+1}), else the held force itself.
void CfdDemCoupling::settle_last_step() {
  const double dt = last_dt_;
  for (std::size_t r = 0; r < ids_.size(); ++r) {
    const auto id = static_cast<std::size_t>(ids_[r]);
    const std::size_t p = index_of_id_[id];
    const Sample s = sample(r);
    const Vec3 pressure = settings_.pressure_force == PressureForce::gradient
                              ? Vec3(-volumes_[id] * s.pressure_gradient)
                              : other_force_[r];
    deferred_[p] =
        (*external_.impulse)[p] - dt * drag_[r] * (s.velocity - velocities_[r]) - dt * pressure;
  }
}

// The weights and void fraction of the grains where they are now; the fluid steps to it (two-way).
void CfdDemCoupling::map_grains() {
  const ParticleStore& store = grains_.particles();
  cfd::FluidSolver& fluid = fluid_.fluid();
  cell_weights_.build(fluid.grid(), fluid.mask(), store.position(), radius_);
  face_weights_.build(fluid.grid(), fluid.mask(), cell_weights_, store.size());
  map_void_fraction(store.id());
  if (settings_.two_way && started_)
    fluid.set_void_fraction(void_fraction_);
  else if (settings_.two_way)
    fluid.start_void_fraction(void_fraction_);
  ids_.assign(store.id().begin(), store.id().end());
  positions_.assign(store.position().begin(), store.position().end());
}

// ε of the cells from the weights of the grains of `ids`, row by row.
void CfdDemCoupling::map_void_fraction(std::span<const std::int64_t> ids) {
  row_volumes_.resize(ids.size());
  for (std::size_t r = 0; r < ids.size(); ++r)
    row_volumes_[r] = volumes_[static_cast<std::size_t>(ids[r])];
  clipped_ = void_fraction(fluid_.fluid().grid(), cell_weights_, row_volumes_,
                           settings_.min_void_fraction, void_fraction_);
}

// K_i from the law, F_i = K_i u_i + the pressure's or buoyancy's force, held for the grains'
// sub-steps, whose length must not exceed the grain's relaxation time m_i / K_i.
void CfdDemCoupling::set_grain_forces(double dt) {
  const ParticleStore& store = grains_.particles();
  const cfd::FluidSettings& fluid = fluid_.fluid().settings();
  const double sub_dt = dt / settings_.grain_sub_steps;
  velocities_.assign(store.velocity().begin(), store.velocity().end());
  drag_.assign(store.size(), 0.0);
  other_force_.assign(store.size(), Vec3::Zero());
  for (std::size_t p = 0; p < store.size(); ++p) {
    const auto id = static_cast<std::size_t>(store.id()[p]);
    const Sample s = sample(p);
    if (s.mapped) {
      const Vec3 slip = s.velocity - store.velocity()[p];
      const DragState state{s.void_fraction, slip.norm(), diameters_[id], fluid.density,
                            fluid.viscosity};
      drag_[p] = law_->coefficient(state) * volumes_[id];
      if (settings_.pressure_force == PressureForce::gradient)
        other_force_[p] = -volumes_[id] * s.pressure_gradient;
      else if (settings_.pressure_force == PressureForce::buoyancy)
        other_force_[p] = -fluid.density * volumes_[id] * gravity_;
    }
    if (sub_dt * drag_[p] > store.mass()[p])
      throw RunError(fmt::format(
          "grain {}: the DEM's step {:.3g} s exceeds its relaxation time in the fluid, m / K = "
          "{:.3g} s (docs/cfd-dem.md, \"One coupled step and the sub-cycles\"); raise "
          "time.sub_steps.dem or lower cfd.max_dt",
          id, sub_dt, store.mass()[p] / drag_[p]));
    (*external_.force)[p] = drag_[p] * s.velocity + other_force_[p];
    (*external_.drag)[p] = drag_[p];
    (*external_.impulse)[p] = Vec3::Zero();
  }
}

// K_f = Σ_i w_if K_i / V_f and S_e,f = Σ_i w_if (K_i v_i - D_i / Δt) / V_f.
void CfdDemCoupling::set_fluid_source(double dt) {
  cfd::FluidSolver& fluid = fluid_.fluid();
  const double volume = fluid.grid().cell_volume();
  for (int a = 0; a < fluid.grid().dimensions(); ++a) {
    std::vector<double>& k = fluid.drag_coefficient()[a];
    std::vector<double>& source = fluid.grain_source()[a];
    std::fill(k.begin(), k.end(), 0.0);
    std::fill(source.begin(), source.end(), 0.0);
    for (std::size_t p = 0; p < ids_.size(); ++p) {
      const double push = drag_[p] * velocities_[p][a] - deferred_[p][a] / dt;
      for (const FaceWeights::Weight& w : face_weights_.of(a, p)) {
        k[w.face] += w.weight * drag_[p] / volume;
        source[w.face] += w.weight * push / volume;
      }
    }
  }
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
  archive.put_vectors(prefix + "positions", positions_);
  archive.put_vectors(prefix + "velocities", velocities_);
  archive.put_doubles(prefix + "drag", drag_);
  archive.put_vectors(prefix + "other_force", other_force_);
}

// The rows of the last exchange, and their weights and void fraction rebuilt from the positions
// then.
void CfdDemCoupling::restore(const StateArchive& archive, const std::string& prefix) {
  const auto times = archive.doubles(prefix + "times");
  if (times.size() != 2)
    throw StateError(prefix + "times: the wrong size");
  started_ = times[0] != 0.0;
  last_dt_ = times[1];
  const auto ids = archive.integers(prefix + "ids");
  ids_.assign(ids.begin(), ids.end());
  positions_ = archive.vectors(prefix + "positions");
  velocities_ = archive.vectors(prefix + "velocities");
  const auto drag = archive.doubles(prefix + "drag");
  drag_.assign(drag.begin(), drag.end());
  other_force_ = archive.vectors(prefix + "other_force");
  const std::size_t n = grains_.particles().size();
  const bool fits = ids_.size() == n && positions_.size() == n && velocities_.size() == n &&
                    drag_.size() == n && other_force_.size() == n;
  if (!fits || std::any_of(ids_.begin(), ids_.end(), [n](std::int64_t id) {
        return id < 0 || static_cast<std::size_t>(id) >= n;
      }))
    throw StateError(fmt::format("{}: the rows do not fit the run's {} grains", prefix, n));
  const cfd::FluidSolver& fluid = fluid_.fluid();
  cell_weights_.build(fluid.grid(), fluid.mask(), positions_, radius_);
  face_weights_.build(fluid.grid(), fluid.mask(), cell_weights_, n);
  map_void_fraction(ids_);
}

}  // namespace partimix::coupling
