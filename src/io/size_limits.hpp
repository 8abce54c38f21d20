#pragma once
// Bounds on what a case may cost (docs/case-reference.md, "limits"): partimix refuses a case
// whose particles, lattice points, steps, series rows or frames would pass them, before it
// spends the memory or the time, naming the key that drives the cost. Each bound is a case key,
// so a user who means a big run raises it (`--set limits.particles=1e8`).
namespace partimix::io {

struct SizeLimits {
  double particles = 2.0e7;       // all methods together; about 10 GB at 500 B per particle
  double lattice_points = 1.0e9;  // points a lattice sampler may visit (shape x spacing)
  double steps = 1.0e8;           // time.end over the first time step
  double series_rows = 1.0e6;     // time.end over time.sample_interval
  double frames = 1.0e5;          // time.end over time.output_interval
  double grid_nodes = 5.0e7;      // nodes of a method's background grid; about 6 GB for MPM
};

}  // namespace partimix::io
