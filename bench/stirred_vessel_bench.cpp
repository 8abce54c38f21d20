// Cost of one SPH step in the stirred vessel of the demo (cases/bohl_planetary_cmc.yaml): the
// planetary plate moved every half step, the power-law viscosity and the full-stress viscous
// operator (docs/sph.md, "Viscous operators"), the rigid-wall ghost velocities and the wall
// acceleration. At about 16k (the case's dp = 7 mm) and 91k particles (dp = 3.5 mm), 1 and 2
// OpenMP threads. The analyses (loads, xi, Lacey) run once per sample interval, not per step,
// and are left out. docs/performance.md records the figures.
#include <benchmark/benchmark.h>

#include "bench_support.hpp"

namespace partimix::bench {
namespace {

void planetary_mixer_cmc(benchmark::State& state, double spacing) {
  time_steps(state, "bohl_planetary_cmc", spacing);
}

BENCHMARK_CAPTURE(planetary_mixer_cmc, 16k, 0.007)->Apply(configure)->Iterations(200);
BENCHMARK_CAPTURE(planetary_mixer_cmc, 91k, 0.0035)->Apply(configure)->Iterations(40);

}  // namespace
}  // namespace partimix::bench
