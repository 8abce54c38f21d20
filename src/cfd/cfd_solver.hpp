#pragma once
// The grid fluid as a method of a run (docs/cfd.md): the staggered grid over the case's domain,
// its cells blocked by the walls, and the fluid's time step (cfd/fluid_solver.hpp). Its
// particles are the open cells, each a fluid point at the cell's centre carrying the cell's
// fluid mass ρ ε V, its `volume` (the heavy phase's with two phases) and velocity, so that the
// analyses of any method's material (kinetic energy, largest speed, profiles, a truck drum's
// discharge) measure the fluid; its frames are the grid's cells (.vti). In a
// rotating frame (cfd.rotating_frame) the grid turns with a wall: the particles' positions and
// velocities and the frames are given in the lab.
#include <memory>
#include <vector>

#include "cfd/config.hpp"
#include "cfd/fluid_frame.hpp"
#include "cfd/fluid_solver.hpp"
#include "cfd/wall_motions.hpp"
#include "particles/grid_frame.hpp"
#include "particles/solver.hpp"

namespace partimix::cfd {

class CfdSolver final : public Solver {
 public:
  // Throws InputError at `cfd.cell_size` for a grid beyond config.max_cells or with no open cell,
  // at `walls[w].motion` for a wall whose surface does not stay in place in the fluid's frame.
  CfdSolver(ParticleStore& store, const Domain& domain, const CfdConfig& config);

  std::string_view name() const override { return "cfd"; }
  const ParticleStore& particles() const override { return store_; }
  const Domain& domain() const override { return domain_; }
  double stable_dt() const override { return fluid_->stable_dt(); }
  void step(double dt) override;
  std::map<std::string, double> derived_parameters() const override;
  const GridFrame* grid_frame() override;
  void save(StateArchive& archive, const std::string& prefix) const override;
  void restore(const StateArchive& archive, const std::string& prefix) override;

  const FluidSolver& fluid() const { return *fluid_; }
  // The frame the grid is in: the lab, or the body of cfd.rotating_frame's wall.
  const FluidFrame& frame() const { return frame_motion_; }
  // For a coupling: the void fraction and the grains' drag of the next step.
  FluidSolver& fluid() { return *fluid_; }

 private:
  static grid::StaggeredGrid make_grid(const Domain& domain, const CfdConfig& config);
  void lay_out_cells();
  void update_cells();
  void set_frame(double dt);
  void set_walls_at(double time);
  void grain_source_cells();

  ParticleStore& store_;
  Domain domain_;
  CfdConfig config_;
  std::unique_ptr<FluidSolver> fluid_;
  FluidFrame frame_motion_;
  WallMotions wall_motions_;
  std::vector<std::int32_t> wall_of_cell_;  // per cell: the wall blocking it, -1 open
  std::vector<std::size_t> open_cells_;     // the cell of each particle
  std::vector<double>* volume_ = nullptr;   // the store's `volume`: the fluid's in each cell
  double time_ = 0.0;
  std::int64_t steps_ = 0;
  GridFrame frame_;
  std::vector<double> frame_velocity_;
  std::vector<double> frame_relative_velocity_;
  std::vector<double> frame_grain_source_;
  std::vector<double> frame_open_;
};

}  // namespace partimix::cfd
