#pragma once
// What the `mpm:` section and the shared walls say for the material point method
// (docs/case-reference.md, "mpm"; docs/mpm.md).
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/vec.hpp"
#include "geometry/motion.hpp"
#include "geometry/shape.hpp"
#include "geometry/surface.hpp"
#include "materials/granular/granular_material.hpp"

namespace partimix::mpm {

// A region filled with material points on a lattice of `spacing` (docs/mpm.md, "Filling").
struct PointFill {
  std::shared_ptr<const geometry::Shape> region;
  double spacing = 0.0;
  int material = 0;  // index into MpmConfig::materials
  int tag = 0;       // the points' tag (1: a tracer for the mixing analyses)
  Vec3 velocity = Vec3::Zero();
  bool geostatic = false;
  std::optional<double> lateral_stress_ratio;  // K0; default Jaky's 1 - sin(atan mu_s)
};

// How a wall acts on the grid nodes on or behind it (docs/mpm.md, "Walls").
enum class GridBoundary { no_slip, slip, friction };

struct GridWall {
  std::shared_ptr<const geometry::Surface> surface;
  geometry::MotionConfig motion;
  GridBoundary boundary = GridBoundary::no_slip;
  double friction = 0.0;  // mu_w, for GridBoundary::friction
};

// An exit plane (docs/mpm.md, "Exits and feeds"): a point beyond it, (x - point) . normal > 0,
// leaves the run and its mass is counted.
struct PointExit {
  Vec3 point = Vec3::Zero();
  Vec3 normal = -Vec3::UnitY();  // unit, the way the material leaves
};

// A feed (docs/mpm.md, "Exits and feeds"): the region is kept full from the top. Its lattice
// (of `spacing`) is cut into columns along gravity; every step, each column gets points on its
// lattice from its top down to a spacing above its highest point, stress-free at the critical
// density, moving with `velocity`.
struct PointFeed {
  std::shared_ptr<const geometry::Shape> region;
  double spacing = 0.0;
  int material = 0;
  int tag = 0;
  Vec3 velocity = Vec3::Zero();
};

struct MpmConfig {
  double cell_size = 0.0;                  // h [m]
  std::string shape_function = "bspline";  // linear | gimp | bspline
  bool apic = true;                        // transfer: apic, else flip
  std::optional<double> filter_time;  // tau [s] of the transfers' filter; auto: 0.06 sqrt(h / |g|)
  bool musl = true;                   // update: musl, else usl
  bool averaged_dilation = false;     // dilation: averaged (tr L through the nodes), else local
  double cfl = 0.3;
  double max_grid_nodes = 5.0e7;  // limits.grid_nodes
  std::vector<materials::GranularMaterial> materials;
  std::vector<PointFill> fills;
  std::vector<GridWall> walls;
  std::vector<PointExit> exits;
  std::vector<PointFeed> feeds;
};

}  // namespace partimix::mpm
