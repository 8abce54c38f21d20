#include "cfd/cfd_solver.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "cfd/blocked_cells.hpp"
#include "cfd/face_stencil.hpp"
#include "core/error.hpp"
#include "particles/store_state.hpp"

namespace partimix::cfd {
namespace {

const InputLocation kCellSize{"", 0, 0, "cfd.cell_size"};

FluidFrame frame_of(const CfdConfig& config) {
  if (config.frame_wall < 0)
    return {};
  return FluidFrame(config.wall_motions[static_cast<std::size_t>(config.frame_wall)]);
}

constexpr int kSamplesAcross = 4;  // α at the start: sample points along each axis of a cell

// The share of each open cell's sample points (kSamplesAcross per axis, evenly spaced) inside
// one of the regions.
std::vector<double> heavy_phase_fraction(
    const FluidSolver& fluid, const std::vector<std::shared_ptr<const geometry::Shape>>& regions) {
  const grid::StaggeredGrid& grid = fluid.grid();
  const int dimensions = grid.dimensions();
  const int count = dimensions == 2 ? kSamplesAcross * kSamplesAcross
                                    : kSamplesAcross * kSamplesAcross * kSamplesAcross;
  std::vector<double> fraction(grid.cell_count(), 0.0);
  grid.for_each_cell([&](const std::array<int, 3>& cell, std::size_t c) {
    if (!fluid.mask().open_cell[c])
      return;
    Vec3 centre = grid.cell_centre(cell[0], cell[1], cell[2]);
    if (dimensions == 2)
      centre[2] = 0.0;
    int inside = 0;
    for (int n = 0; n < count; ++n) {
      Vec3 x = centre;
      int rest = n;
      for (int a = 0; a < dimensions; ++a, rest /= kSamplesAcross)
        x[a] += ((rest % kSamplesAcross + 0.5) / kSamplesAcross - 0.5) * grid.spacing(a);
      const bool in_any = std::any_of(regions.begin(), regions.end(), [&](const auto& region) {
        return region->signed_distance(x) <= 0.0;
      });
      inside += in_any ? 1 : 0;
    }
    fraction[c] = static_cast<double>(inside) / count;
  });
  return fraction;
}

}  // namespace

// The domain's box with the whole count of cells nearest to its length over cfd.cell_size along
// each axis; in 2D one cell of unit depth centred on z = 0.
grid::StaggeredGrid CfdSolver::make_grid(const Domain& domain, const CfdConfig& config) {
  std::array<int, 3> cells{1, 1, 1};
  Vec3 spacing = Vec3::Ones();
  Vec3 origin = domain.lo;
  for (int axis = 0; axis < domain.dimensions; ++axis) {
    const double length = domain.hi[axis] - domain.lo[axis];
    const double count = std::max(1.0, std::round(length / config.cell_size));
    if (!(count <= config.max_cells))
      throw InputError(kCellSize, fmt::format("makes {:.3g} cells along one axis, more than "
                                              "limits.grid_nodes = {:.3g}",
                                              count, config.max_cells));
    cells[axis] = static_cast<int>(count);
    spacing[axis] = length / count;
  }
  if (domain.dimensions == 2)
    origin[2] = -0.5;
  try {
    return grid::StaggeredGrid(domain.dimensions, origin, cells, spacing, domain.periodic,
                               config.max_cells);
  } catch (const InputError& error) {
    throw InputError(kCellSize, error.message());
  }
}

CfdSolver::CfdSolver(ParticleStore& store, const Domain& domain, const CfdConfig& config)
    : store_(store),
      domain_(domain),
      config_(config),
      frame_motion_(frame_of(config)),
      wall_motions_(config.wall_motions, frame_motion_) {
  const grid::StaggeredGrid grid = make_grid(domain, config);
  const int moved = wall_motions_.first_not_in_place(grid, config.walls, config.in_place_samples);
  if (moved >= 0)
    throw InputError(
        InputLocation{"", 0, 0, fmt::format("walls[{}].motion", moved)},
        "the grid fluid blocks a wall's cells once, so the wall's surface must stay in place in "
        "the fluid's frame: a fixed or sliding wall, a surface of revolution turning about its "
        "own axis, or the body that cfd.rotating_frame turns with (docs/cfd.md, \"Moving walls "
        "and the rotating frame\")");
  BlockedCells blocked = blocked_by_walls(grid, config.walls, config.wall_shapes);
  wall_of_cell_ = std::move(blocked.wall);
  fluid_ = std::make_unique<FluidSolver>(grid, blocked.mask, config.sides, config.settings);
  volume_ = &store_.add_scalar("volume", "m^3", false).values;
  if (fluid_->two_phases())
    fluid_->set_phase_fraction(heavy_phase_fraction(*fluid_, config.heavy_regions));
  lay_out_cells();
  update_cells();
}

void CfdSolver::lay_out_cells() {
  const grid::StaggeredGrid& grid = fluid_->grid();
  const FlowMask& mask = fluid_->mask();
  for (std::size_t c = 0; c < grid.cell_count(); ++c)
    if (mask.open_cell[c])
      open_cells_.push_back(c);
  if (open_cells_.empty())
    throw InputError(kCellSize, "the walls block every cell of the grid");
  store_.resize(open_cells_.size());
  for (std::size_t p = 0; p < open_cells_.size(); ++p) {
    const auto [i, j, k] = grid.cell_coordinates(open_cells_[p]);
    store_.id()[p] = static_cast<std::int64_t>(open_cells_[p]);
    store_.kind()[p] = static_cast<std::int32_t>(ParticleKind::fluid);
    Vec3 x = grid.cell_centre(i, j, k);
    if (grid.dimensions() == 2)
      x[2] = 0.0;
    store_.position()[p] = x;
  }
  frame_ = GridFrame{};
  frame_.dimensions = grid.dimensions();
  frame_.origin = grid.origin();
  for (int axis = 0; axis < 3; ++axis) {
    frame_.cells[axis] = grid.cells(axis);
    frame_.spacing[axis] = grid.spacing(axis);
  }
  frame_open_.assign(grid.cell_count(), 0.0);
  for (const std::size_t c : open_cells_)
    frame_open_[c] = 1.0;
}

// The particles' place, velocity (in the lab), mass ρ ε V and volume, the fluid's ε V (with two
// phases the heavy phase's α ε V).
void CfdSolver::update_cells() {
  const grid::StaggeredGrid& grid = fluid_->grid();
  const std::vector<double>& eps = fluid_->void_fraction();
  const std::vector<double>& density = fluid_->density();
  const geometry::RigidPose pose = frame_motion_.pose(time_);
  for (std::size_t p = 0; p < open_cells_.size(); ++p) {
    const auto [i, j, k] = grid.cell_coordinates(open_cells_[p]);
    const Vec3 u = fluid_->cell_velocity(i, j, k);
    const std::size_t c = open_cells_[p];
    store_.mass()[p] = density[c] * eps[c] * grid.cell_volume();
    (*volume_)[p] = fluid_->phase_fraction()[c] * eps[c] * grid.cell_volume();
    if (!frame_motion_.rotating()) {
      store_.velocity()[p] = u;
      continue;
    }
    Vec3 x = grid.cell_centre(i, j, k);
    if (grid.dimensions() == 2)
      x[2] = 0.0;
    store_.position()[p] = pose.place(x);
    store_.velocity()[p] = lab_velocity(pose, x, u);
  }
}

void CfdSolver::step(double dt) {
  set_frame(dt);
  const LinearSolve pressure = fluid_->step(dt);
  const LinearSolve& momentum = fluid_->momentum_solve();
  for (const auto& [solve, what] : {std::pair{pressure, "the pressure correction"},
                                    std::pair{momentum, "the momentum predictor"}}) {
    if (!solve.converged)
      throw RunError(fmt::format(
          "{} did not converge at t = {:.6g} s: relative residual {:.3g} after {} iterations "
          "(cfd.pressure_tolerance {:.3g}, cfd.momentum_tolerance {:.3g}, cfd.max_iterations {})",
          what, time_, solve.residual, solve.iterations, config_.settings.pressure_tolerance,
          config_.settings.momentum_tolerance, config_.settings.max_iterations));
  }
  time_ += dt;
  ++steps_;
  update_cells();
}

// The frame's forces at the middle of the step, the walls' velocities at its end (the implicit
// viscous term's).
void CfdSolver::set_frame(double dt) {
  if (frame_motion_.rotating())
    fluid_->set_frame_forces(frame_motion_.forces(time_ + 0.5 * dt, config_.settings.gravity));
  set_walls_at(time_ + dt);
}

void CfdSolver::set_walls_at(double time) {
  if (!wall_motions_.any_moving())
    return;
  wall_motions_.set_time(time);
  fluid_->set_wall_velocities([&](const Vec3& x, std::size_t cell) {
    return wall_motions_.velocity(static_cast<std::size_t>(wall_of_cell_[cell]), x);
  });
}

std::map<std::string, double> CfdSolver::derived_parameters() const {
  const grid::StaggeredGrid& grid = fluid_->grid();
  std::map<std::string, double> parameters{
      {"cells [-]", static_cast<double>(grid.cell_count())},
      {"open cells [-]", static_cast<double>(open_cells_.size())}};
  const materials::RheologyConfig& rheology = config_.settings.rheology;
  if (rheology.model == "newtonian")
    parameters["kinematic viscosity [m^2/s]"] = rheology.viscosity / config_.settings.density;
  const char* names[] = {"x", "y", "z"};
  for (int axis = 0; axis < grid.dimensions(); ++axis)
    parameters[fmt::format("cell size {} [m]", names[axis])] = grid.spacing(axis);
  return parameters;
}

// Velocity (3 components) at the cell centres, pressure, void fraction, the grains' source S_p
// (3 components), the viscosity and the open flag, per cell, and with two phases the heavy
// phase's fraction α and the density; in a rotating frame the image turns
// with the grid (its direction matrix), the velocity is the lab's and relative_velocity the
// velocity relative to the frame, both in lab directions.
const GridFrame* CfdSolver::grid_frame() {
  const grid::StaggeredGrid& grid = fluid_->grid();
  const geometry::RigidPose pose = frame_motion_.pose(time_);
  frame_velocity_.assign(3 * grid.cell_count(), 0.0);
  frame_relative_velocity_.assign(frame_motion_.rotating() ? 3 * grid.cell_count() : 0, 0.0);
  for (const std::size_t c : open_cells_) {
    const auto [i, j, k] = grid.cell_coordinates(c);
    const Vec3 u = fluid_->cell_velocity(i, j, k);
    Vec3 lab = u;
    if (frame_motion_.rotating()) {
      Vec3 x = grid.cell_centre(i, j, k);
      if (grid.dimensions() == 2)
        x[2] = 0.0;
      lab = lab_velocity(pose, x, u);
      const Vec3 relative = pose.rotation * u;
      for (int a = 0; a < 3; ++a)
        frame_relative_velocity_[3 * c + static_cast<std::size_t>(a)] = relative[a];
    }
    for (int a = 0; a < 3; ++a)
      frame_velocity_[3 * c + static_cast<std::size_t>(a)] = lab[a];
  }
  grain_source_cells();
  frame_.origin = pose.place(grid.origin());
  frame_.direction = pose.rotation;
  frame_.cell_arrays = {{"velocity", 3, frame_velocity_},
                        {"pressure", 1, fluid_->pressure()},
                        {"void_fraction", 1, fluid_->void_fraction()},
                        {"grain_source", 3, frame_grain_source_},
                        {"viscosity", 1, fluid_->viscosity()},
                        {"open", 1, frame_open_}};
  if (frame_motion_.rotating())
    frame_.cell_arrays.push_back({"relative_velocity", 3, frame_relative_velocity_});
  if (fluid_->two_phases()) {
    frame_.cell_arrays.push_back({"phase_fraction", 1, fluid_->phase_fraction()});
    frame_.cell_arrays.push_back({"density", 1, fluid_->density()});
  }
  return &frame_;
}

// S_p = S_e - K_f u, the grains' force on the fluid per unit volume (docs/cfd-dem.md, "The
// source S_p"), at the cell centres (the mean of the faces on each axis), in lab directions.
void CfdSolver::grain_source_cells() {
  const grid::StaggeredGrid& grid = fluid_->grid();
  const FaceArrays& k = fluid_->drag_coefficient();
  const FaceArrays& source = fluid_->grain_source();
  const FaceArrays& u = fluid_->velocity();
  const Mat3 turn = frame_motion_.pose(time_).rotation;
  frame_grain_source_.assign(3 * grid.cell_count(), 0.0);
  for (const std::size_t c : open_cells_) {
    const auto cell = grid.cell_coordinates(c);
    Vec3 force = Vec3::Zero();
    for (int a = 0; a < grid.dimensions(); ++a) {
      Coordinates upper = cell;
      upper[a] = grid.wrap_face(a, cell[a] + 1);
      for (const std::size_t f : {face_index(grid, a, cell), face_index(grid, a, upper)})
        force[a] += 0.5 * (source[a][f] - k[a][f] * u[a][f]);
    }
    const Vec3 lab = turn * force;
    for (int a = 0; a < 3; ++a)
      frame_grain_source_[3 * c + static_cast<std::size_t>(a)] = lab[a];
  }
}

void CfdSolver::save(StateArchive& archive, const std::string& prefix) const {
  save_store(store_, archive, prefix);
  const FaceArrays& velocity = fluid_->velocity();
  for (int axis = 0; axis < 3; ++axis)
    archive.put_doubles(fmt::format("{}velocity_{}", prefix, axis), velocity[axis]);
  for (int axis = 0; axis < 3; ++axis)
    archive.put_doubles(fmt::format("{}previous_velocity_{}", prefix, axis),
                        fluid_->previous_velocity()[axis]);
  archive.put_doubles(prefix + "pressure", fluid_->pressure());
  archive.put_doubles(prefix + "correction", fluid_->last_correction());
  archive.put_doubles(prefix + "void_fraction", fluid_->void_fraction());
  if (fluid_->two_phases())
    archive.put_doubles(prefix + "phase_fraction", fluid_->phase_fraction());
  archive.put_scalar(prefix + "time", time_);
  archive.put_integers(prefix + "steps", std::vector<std::int64_t>{steps_});
}

namespace {

std::vector<double> sized(const StateArchive& archive, const std::string& path, std::size_t size) {
  const std::span<const double> values = archive.doubles(path);
  if (values.size() != size)
    throw StateError(fmt::format("{}: {} values, the grid has {}", path, values.size(), size));
  return {values.begin(), values.end()};
}

}  // namespace

void CfdSolver::restore(const StateArchive& archive, const std::string& prefix) {
  restore_store(store_, archive, prefix, false);
  const grid::StaggeredGrid& grid = fluid_->grid();
  FaceArrays velocity;
  for (int axis = 0; axis < 3; ++axis)
    velocity[static_cast<std::size_t>(axis)] =
        sized(archive, fmt::format("{}velocity_{}", prefix, axis), grid.face_count(axis));
  const std::vector<double> pressure = sized(archive, prefix + "pressure", grid.cell_count());
  const std::vector<double> correction = sized(archive, prefix + "correction", grid.cell_count());
  const std::vector<double> eps = sized(archive, prefix + "void_fraction", grid.cell_count());
  time_ = archive.scalar(prefix + "time");
  set_walls_at(time_);  // as the last step left them, for the viscosity the restore takes
  fluid_->restore(velocity, pressure, correction, eps);
  if (fluid_->two_phases())
    fluid_->set_phase_fraction(sized(archive, prefix + "phase_fraction", grid.cell_count()));
  FaceArrays previous;
  for (int axis = 0; axis < 3; ++axis)
    previous[static_cast<std::size_t>(axis)] =
        sized(archive, fmt::format("{}previous_velocity_{}", prefix, axis), grid.face_count(axis));
  fluid_->restore_previous_velocity(previous);
  const auto steps = archive.integers(prefix + "steps");
  if (steps.size() != 1)
    throw StateError(prefix + "steps: the wrong size");
  steps_ = steps[0];
}

}  // namespace partimix::cfd
