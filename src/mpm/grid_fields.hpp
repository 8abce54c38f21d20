#pragma once
// What the grid's nodes hold during an MPM step (docs/mpm.md, "Balance laws"): mass, momentum,
// force, the velocity before and after the forces, the averaged dilation. Sized once for the grid;
// only the nodes in use (grid::NodeBuckets::active_nodes) are written and read each step.
#include <vector>

#include "core/vec.hpp"

namespace partimix::mpm {

struct GridFields {
  std::vector<double> mass;
  std::vector<Vec3> momentum;
  std::vector<Vec3> force;
  std::vector<Vec3> velocity;      // momentum / mass
  std::vector<Vec3> velocity_new;  // after the forces and the walls
  std::vector<double> dilation;    // theta_i, the mass-weighted mean of the points' tr L

  void resize(std::size_t nodes) {
    mass.assign(nodes, 0.0);
    momentum.assign(nodes, Vec3::Zero());
    force.assign(nodes, Vec3::Zero());
    velocity.assign(nodes, Vec3::Zero());
    velocity_new.assign(nodes, Vec3::Zero());
    dilation.assign(nodes, 0.0);
  }
};

}  // namespace partimix::mpm
