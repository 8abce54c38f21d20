// Cost of one SPH step on the 3D dam break (DESIGN.md, "Data and speed"), in particle-steps per
// second and bytes per particle, at about 25k, 100k and 400k particles (fluid + wall) and at 1
// and 2 OpenMP threads, with the variable smoothing length at 25k, and on DualSPHysics' own 3D
// dam break. docs/performance.md records the
// figures and how they were taken.
#include <benchmark/benchmark.h>

#include "bench_support.hpp"

namespace partimix::bench {
namespace {

void dam_break_3d(benchmark::State& state, double spacing) {
  time_steps(state, "dam_break_3d", spacing);
}

BENCHMARK_CAPTURE(dam_break_3d, 25k, 0.025)->Apply(configure)->Iterations(200);
BENCHMARK_CAPTURE(dam_break_3d, 100k, 0.0135)->Apply(configure)->Iterations(60);
BENCHMARK_CAPTURE(dam_break_3d, 400k, 0.0075)->Apply(configure)->Iterations(20);

// The 25k case with the variable smoothing length (docs/sph.md, "Variable smoothing length"):
// the kernel's scales per particle, two table reads per fluid pair and a search 1.05 supports
// wide.
void dam_break_3d_variable_h(benchmark::State& state) {
  time_steps(state, "dam_break_3d", {"sph.spacing=0.025", "sph.smoothing_length=variable"});
}

BENCHMARK(dam_break_3d_variable_h)->Apply(configure)->Iterations(200);

// DualSPHysics' CaseDambreak as cases/dam_break_dualsphysics.yaml sets it up (174k particles,
// h = sqrt(3) dp, one wall layer): the side-by-side comparison of docs/performance.md.
void dam_break_dualsphysics(benchmark::State& state) {
  time_steps(state, "dam_break_dualsphysics", 0.0085);
}

BENCHMARK(dam_break_dualsphysics)->Apply(configure)->Iterations(20);

}  // namespace
}  // namespace partimix::bench
