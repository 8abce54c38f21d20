// Cost of one step of the multi-material SPH scheme on the gel-fuel droplet of
// cases/gel_droplet_2d.yaml (docs/performance.md, "Multi-material SPH"): the seed's 7,854
// particles at 10 um and a finer droplet of about 31,000 at 5 um, at 1 and 2 OpenMP threads.
// Each step evaluates the continuity pairing's rates, surface tension, conduction,
// the temperature and the shell's stress.
#include <benchmark/benchmark.h>

#include "bench_support.hpp"

namespace partimix::bench {
namespace {

void gel_droplet(benchmark::State& state, double spacing) {
  time_steps(state, "gel_droplet_2d", spacing);
}

BENCHMARK_CAPTURE(gel_droplet, 8k, 1.0e-5)->Apply(configure)->Iterations(200);
BENCHMARK_CAPTURE(gel_droplet, 31k, 5.0e-6)->Apply(configure)->Iterations(60);

}  // namespace
}  // namespace partimix::bench
