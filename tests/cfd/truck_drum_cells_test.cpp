// The grid fluid in a truck drum (docs/cfd.md, "Walls: blocked cells"): the drum's contact
// surface is a two-sided shell with no behind, so the grid blocks what lies outside its cavity.
// Held, over every cell of a 40³ grid round the small tilted drum of the truck_drum tests: a
// cell whose centre lies more than a cell inside the cavity (clear of shell and blades) is open;
// one more than a cell outside the shell and short of the opening's plane is blocked (by the
// drum, wall 0); one more than a cell beyond the opening's plane is open; and one whose centre
// lies within 0.4 of a cell of a blade (4 mm thick, a cell 10 mm) is blocked, so that the grid's
// blades have no holes.
#include <gtest/gtest.h>

#include <string>

#include "app/simulation.hpp"
#include "cfd/cfd_solver.hpp"
#include "geometry/truck_drum_shape.hpp"
#include "support/case_run.hpp"
#include "support/small_truck_drum_case.hpp"

namespace partimix::cfd {
namespace {

TEST(TruckDrumCells, TheGridBlocksWhatLiesOutsideTheCavity) {
  std::string text = test_support::kSmallTruckDrumCase;
  const std::size_t dem = text.find("dem:\n");
  const std::size_t walls = text.find("walls:\n");
  text.replace(dem, walls - dem,
               "fluid: {density: 1000, viscosity: 1.0e-3}\ncfd: {cell_size: 0.01}\n");
  text.replace(0, text.find('\n'), "solver: cfd");
  const test_support::TempDir dir;
  const io::Case the_case = test_support::load_case_text(dir, text);
  app::Simulation simulation = app::build_simulation(the_case);
  const auto& solver = dynamic_cast<const CfdSolver&>(*simulation.methods[0].solver);
  const FluidSolver& fluid = solver.fluid();
  const auto& drum = dynamic_cast<const geometry::TruckDrumShape&>(*the_case.walls[0].shape);
  const grid::StaggeredGrid& grid = fluid.grid();
  const double h = grid.spacing(0);
  int inside = 0;
  int outside = 0;
  int beyond = 0;
  int blade = 0;
  grid.for_each_cell([&](const std::array<int, 3>& c, std::size_t index) {
    const Vec3 x = grid.cell_centre(c[0], c[1], c[2]);
    const bool open = fluid.mask().open_cell[index] != 0;
    const Vec3 local = drum.to_drum(x);
    const double past_opening = local.z() - drum.drum().length();
    if (past_opening < 0.0 && drum.drum().blade_distance(local) < 0.4 * h) {
      EXPECT_FALSE(open) << x.transpose();
      ++blade;
    }
    if (past_opening > h) {
      EXPECT_TRUE(open) << x.transpose();
      ++beyond;
    } else if (past_opening < -h && drum.signed_distance(x) > h) {
      EXPECT_FALSE(open) << x.transpose();
      ++outside;
    } else if (drum.signed_distance(x) < -h) {
      EXPECT_TRUE(open) << x.transpose();
      ++inside;
    }
  });
  EXPECT_GT(inside, 100);
  EXPECT_GT(outside, 1000);
  EXPECT_GT(beyond, 1000);
  EXPECT_GT(blade, 100);
}

}  // namespace
}  // namespace partimix::cfd
