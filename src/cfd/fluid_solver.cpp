#include "cfd/fluid_solver.hpp"

#include <algorithm>
#include <cmath>

#include "cfd/cell_shear_rate.hpp"
#include "cfd/face_stencil.hpp"
#include "cfd/frame_forces.hpp"
#include "cfd/transpose_viscous.hpp"

namespace partimix::cfd {

FluidSolver::FluidSolver(const grid::StaggeredGrid& grid, const FlowMask& mask,
                         const BoxSides& sides, const FluidSettings& settings)
    : grid_(grid),
      mask_(mask),
      sides_(sides),
      settings_(settings),
      velocity_(face_arrays(grid, 0.0)),
      extrapolated_(face_arrays(grid, 0.0)),
      pressure_(grid.cell_count(), 0.0),
      cell_void_fraction_(grid.cell_count(), 1.0),
      old_cell_void_fraction_(grid.cell_count(), 1.0),
      cell_viscosity_(grid.cell_count(), settings.rheology.viscosity),
      phase_fraction_(grid.cell_count(), 1.0),
      cell_density_(grid.cell_count(), settings.density),
      face_density_(face_arrays(grid, settings.density)),
      compression_(settings.light_phase ? settings.light_phase->compression : 0.0),
      void_fraction_(face_arrays(grid, 1.0)),
      old_void_fraction_(face_arrays(grid, 1.0)),
      drag_coefficient_(face_arrays(grid, 0.0)),
      grain_source_(face_arrays(grid, 0.0)),
      convection_(face_arrays(grid, 0.0)),
      transpose_(face_arrays(grid, 0.0)),
      diagonal_(face_arrays(grid, 0.0)),
      rhs_(face_arrays(grid, 0.0)),
      coefficient_(face_arrays(grid, 0.0)),
      source_(grid.cell_count(), 0.0),
      correction_(grid.cell_count(), 0.0),
      predictor_(settings.momentum_tolerance, settings.max_iterations),
      projection_(settings.pressure_tolerance, settings.max_iterations) {
  if (settings.rheology.model != "newtonian")
    rheology_.emplace(settings.rheology);
  mark_outlets(grid_, sides_, mask_);
  set_side_faces();
  list_wall_faces();
  previous_velocity_ = velocity_;
  frame_forces_.gravity = settings.gravity;
  predictor_.lay_out(grid_, mask_);
  projection_.lay_out(grid_, mask_);
  update_density();
  update_viscosity();
}

// The faces on the box's sides carry the side's velocity normal to it.
void FluidSolver::set_side_faces() {
  for (int axis = 0; axis < grid_.dimensions(); ++axis) {
    if (grid_.periodic(axis))
      continue;
    grid_.for_each_face(axis, [&](const Coordinates& f, std::size_t index) {
      if (f[axis] == 0 || f[axis] == grid_.cells(axis))
        velocity_[axis][index] = box_side(sides_, axis, f[axis] == 0 ? -1 : 1).velocity[axis];
    });
  }
}

void FluidSolver::list_wall_faces() {
  for (int axis = 0; axis < grid_.dimensions(); ++axis) {
    wall_faces_.slot[axis].assign(grid_.face_count(axis), -1);
    grid_.for_each_face(axis, [&](const Coordinates& f, std::size_t index) {
      if (mask_.open_face[axis][index] || mask_.outlet_face[axis][index])
        return;
      for (const int side : {-1, 1}) {
        Coordinates cell;
        if (!cell_beside(grid_, axis, f, side, cell) || cell[axis] >= grid_.cells(axis))
          return;
      }
      for (const int side : {-1, 1}) {
        Coordinates cell;
        cell_beside(grid_, axis, f, side, cell);
        const std::size_t c = cell_index(grid_, cell);
        if (!mask_.open_cell[c]) {
          wall_faces_.slot[axis][index] = static_cast<std::int32_t>(wall_faces_.faces[axis].size());
          wall_faces_.faces[axis].emplace_back(index, c);
          wall_faces_.velocity[axis].push_back(Vec3::Zero());
          return;
        }
      }
    });
  }
}

void FluidSolver::set_wall_velocities(
    const std::function<Vec3(const Vec3&, std::size_t)>& velocity_at) {
  predictor_.set_wall_velocities(grid_, velocity_at);
  for (int axis = 0; axis < grid_.dimensions(); ++axis)
    for (std::size_t k = 0; k < wall_faces_.faces[axis].size(); ++k) {
      const auto [face, cell] = wall_faces_.faces[axis][k];
      const auto f = grid_.face_coordinates(axis, face);
      wall_faces_.velocity[axis][k] = velocity_at(grid_.face_centre(axis, f[0], f[1], f[2]), cell);
      velocity_[axis][face] = wall_faces_.velocity[axis][k][axis];
    }
}

double FluidSolver::stable_dt() const {
  double dt = settings_.max_dt;
  for (int axis = 0; axis < grid_.dimensions(); ++axis) {
    double fastest = 0.0;
    for (const double u : velocity_[axis])
      fastest = std::max(fastest, std::abs(u));
    if (fastest > 0.0)
      dt = std::min(dt, settings_.cfl * grid_.spacing(axis) / fastest);
  }
  if (two_phases())
    dt = std::min(dt, phase_transport_.stable_dt(grid_, mask_, void_fraction_, velocity_,
                                                 cell_void_fraction_));
  for (const BoxSide& side : sides_)
    for (int axis = 0; axis < grid_.dimensions(); ++axis)
      if (side.velocity[axis] != 0.0)
        dt = std::min(dt, settings_.cfl * grid_.spacing(axis) / std::abs(side.velocity[axis]));
  return dt;
}

// ε_f: the mean of the two cells, on an outlet face its one cell's.
void FluidSolver::faces_from_cells(const std::vector<double>& cells, FaceArrays& faces) const {
  for (int a = 0; a < grid_.dimensions(); ++a)
    grid_.for_each_face(a, [&](const Coordinates& f, std::size_t index) {
      if (mask_.outlet_face[a][index]) {
        Coordinates cell = f;
        cell[a] = f[a] == 0 ? 0 : f[a] - 1;
        faces[a][index] = cells[cell_index(grid_, cell)];
        return;
      }
      if (!mask_.open_face[a][index])
        return;
      Coordinates below = f;
      below[a] = grid_.wrap_cell(a, f[a] - 1);
      const std::size_t above = cell_index(grid_, f);
      faces[a][index] = 0.5 * (cells[cell_index(grid_, below)] + cells[above]);
    });
}

void FluidSolver::set_void_fraction(std::span<const double> cells) {
  std::swap(old_cell_void_fraction_, cell_void_fraction_);
  std::swap(old_void_fraction_, void_fraction_);
  std::copy(cells.begin(), cells.end(), cell_void_fraction_.begin());
  faces_from_cells(cell_void_fraction_, void_fraction_);
}

void FluidSolver::start_void_fraction(std::span<const double> cells) {
  set_void_fraction(cells);
  set_void_fraction(cells);
}

// D_f = ρ_f ε_f^{n+1} / Δt + K_f, r_f = ρ_f (ε_f^n u_f / Δt - C_f) + T_f - ε_f^{n+1} (p_above -
// p_below) / h + ε_f^{n+1} ρ_f g + S_e,f, with C_f the convection of unit density, and the
// projection's a_f = ε_f^{n+1} / D_f (Δt / ρ_f without grains).
void FluidSolver::explicit_terms(double dt) {
  for (int a = 0; a < grid_.dimensions(); ++a)
    grid_.for_each_face(a, [&](const Coordinates& f, std::size_t index) {
      if (!mask_.open_face[a][index])
        return;
      const double rho = face_density_[a][index];
      const double eps = void_fraction_[a][index];
      const double gradient = gradient_across(grid_, a, f, pressure_);
      diagonal_[a][index] = rho * eps / dt + drag_coefficient_[a][index];
      rhs_[a][index] =
          rho * (old_void_fraction_[a][index] * velocity_[a][index] / dt - convection_[a][index]) +
          transpose_[a][index] - eps * gradient + eps * rho * frame_forces_.gravity[a] +
          grain_source_[a][index];
      coefficient_[a][index] = eps / diagonal_[a][index];
    });
  for (int a = 0; a < grid_.dimensions(); ++a)
    for (std::size_t index = 0; index < coefficient_[a].size(); ++index)
      if (mask_.outlet_face[a][index])
        coefficient_[a][index] = dt / face_density_[a][index];
  for (std::size_t c = 0; c < source_.size(); ++c)
    source_[c] = (cell_void_fraction_[c] - old_cell_void_fraction_[c]) / dt;
}

// η(γ̇) of each open cell from the present velocity (a non-Newtonian fluid); with two phases
// α η_heavy + (1 - α) η_light, α clipped to [0, 1]. Taken whenever the velocity or α is set (at
// the start, on a restore, after each step), so that a coupling reads, and the next step uses,
// the viscosity of the present state.
void FluidSolver::update_viscosity() {
  if (!rheology_ && !two_phases())
    return;
  if (rheology_)
    cell_shear_rates(grid_, mask_, sides_, wall_faces_, velocity_, shear_rate_);
  for (std::size_t c = 0; c < cell_viscosity_.size(); ++c) {
    if (!mask_.open_cell[c]) {
      cell_viscosity_[c] = 0.0;
      continue;
    }
    const double heavy =
        rheology_ ? rheology_->viscosity(shear_rate_[c]) : settings_.rheology.viscosity;
    if (!two_phases()) {
      cell_viscosity_[c] = heavy;
      continue;
    }
    const double alpha = std::clamp(phase_fraction_[c], 0.0, 1.0);
    cell_viscosity_[c] = alpha * heavy + (1.0 - alpha) * settings_.light_phase->viscosity;
  }
}

// ρ_c = α ρ_heavy + (1 - α) ρ_light, α clipped to [0, 1], and the faces' from the cells'.
void FluidSolver::update_density() {
  if (!two_phases())
    return;
  const double light = settings_.light_phase->density;
  for (std::size_t c = 0; c < cell_density_.size(); ++c)
    cell_density_[c] =
        light + (settings_.density - light) * std::clamp(phase_fraction_[c], 0.0, 1.0);
  faces_from_cells(cell_density_, face_density_);
}

void FluidSolver::set_phase_fraction(std::span<const double> cells) {
  std::copy(cells.begin(), cells.end(), phase_fraction_.begin());
  update_density();
  update_viscosity();
}

LinearSolve FluidSolver::step(double dt) {
  convective_term(grid_, mask_, sides_, settings_.convection, 1.0, old_void_fraction_, velocity_,
                  convection_);
  transpose_viscous_term(grid_, mask_, cell_void_fraction_, cell_viscosity_, velocity_, transpose_);
  explicit_terms(dt);
  if (frame_forces_.rotating) {
    for (int a = 0; a < grid_.dimensions(); ++a)
      for (std::size_t f = 0; f < velocity_[a].size(); ++f) {
        extrapolated_[a][f] = 1.5 * velocity_[a][f] - 0.5 * previous_velocity_[a][f];
        previous_velocity_[a][f] = velocity_[a][f];
      }
    add_frame_forces(grid_, mask_, frame_forces_, face_density_, void_fraction_, extrapolated_,
                     rhs_);
  }
  momentum_solve_ = predictor_.solve(grid_, sides_, cell_void_fraction_, cell_viscosity_, diagonal_,
                                     rhs_, velocity_);
  extrapolate_to_outlets();
  const LinearSolve pressure = projection_.project(grid_, mask_, void_fraction_, coefficient_,
                                                   source_, velocity_, correction_);
  for (std::size_t c = 0; c < pressure_.size(); ++c)
    pressure_[c] += correction_[c];
  if (two_phases()) {
    phase_transport_.advance(grid_, mask_, void_fraction_, velocity_, old_cell_void_fraction_,
                             cell_void_fraction_, dt, phase_fraction_);
    compression_.apply(grid_, mask_, void_fraction_, velocity_, cell_void_fraction_, dt,
                       phase_fraction_);
    update_density();
  }
  update_viscosity();
  return pressure;
}

// u* on an outlet face: that of the face one cell inside (zero gradient across the outlet).
void FluidSolver::extrapolate_to_outlets() {
  for (int a = 0; a < grid_.dimensions(); ++a)
    grid_.for_each_face(a, [&](const Coordinates& f, std::size_t index) {
      if (!mask_.outlet_face[a][index])
        return;
      Coordinates inside = f;
      inside[a] = f[a] == 0 ? 1 : f[a] - 1;
      velocity_[a][index] = velocity_[a][face_index(grid_, a, inside)];
    });
}

void FluidSolver::restore(const FaceArrays& velocity, const std::vector<double>& pressure,
                          const std::vector<double>& correction,
                          const std::vector<double>& void_fraction) {
  start_void_fraction(void_fraction);
  velocity_ = velocity;
  previous_velocity_ = velocity;
  pressure_ = pressure;
  correction_ = correction;
  projection_.set_guess(correction_);
  update_viscosity();
}

Vec3 FluidSolver::cell_velocity(int i, int j, int k) const {
  Vec3 u = Vec3::Zero();
  const Coordinates c{i, j, k};
  for (int a = 0; a < grid_.dimensions(); ++a) {
    Coordinates upper = c;
    upper[a] = grid_.wrap_face(a, c[a] + 1);
    u[a] =
        0.5 * (velocity_[a][face_index(grid_, a, c)] + velocity_[a][face_index(grid_, a, upper)]);
  }
  return u;
}

}  // namespace partimix::cfd
