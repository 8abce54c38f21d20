// Cost of one SPH step on the 3D dam break (DESIGN.md, "Data and speed"), in particle-steps per
// second and bytes per particle, at about 25k, 100k and 400k particles (fluid + wall) and at 1
// and 2 OpenMP threads. docs/performance.md records the figures and how they were taken.
//
// peak_rss_bytes_per_particle divides the peak resident set of the whole process so far by the
// particles of this benchmark, so the sizes are registered smallest first: each figure is then
// the peak of its own size (or of an equal one), not of a larger run before it.
#include <benchmark/benchmark.h>
#include <omp.h>
#include <sys/resource.h>

#include <algorithm>
#include <cstdint>
#include <string>

#include "app/simulation.hpp"
#include "io/case.hpp"

namespace partimix {
namespace {

constexpr int warm_up_steps = 20;

app::Simulation build_dam_break(double spacing) {
  const std::string path = std::string(PARTIMIX_SOURCE_DIR) + "/cases/dam_break_3d.yaml";
  return app::build_simulation(io::load_case(path, {"sph.spacing=" + std::to_string(spacing)}));
}

void step(Solver& solver) {
  solver.step(solver.stable_dt());
}

double peak_rss_bytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) * 1024.0;  // ru_maxrss is in KiB on Linux
}

void report(benchmark::State& state, const ParticleStore& store) {
  const auto particles = static_cast<double>(store.size());
  const auto fluid = std::count_if(store.kind().begin(), store.kind().end(), [](std::int32_t k) {
    return k == static_cast<std::int32_t>(ParticleKind::fluid);
  });
  const auto particle_steps = static_cast<double>(state.iterations()) * particles;
  state.SetItemsProcessed(static_cast<std::int64_t>(particle_steps));
  state.counters["particle_steps_per_s"] =
      benchmark::Counter(particle_steps, benchmark::Counter::kIsRate);
  state.counters["particles"] = particles;
  state.counters["fluid_particles"] = static_cast<double>(fluid);
  state.counters["store_bytes_per_particle"] = static_cast<double>(store.bytes()) / particles;
  state.counters["peak_rss_bytes_per_particle"] = peak_rss_bytes() / particles;
}

// state.range(0): the number of OpenMP threads.
void dam_break_3d(benchmark::State& state, double spacing) {
  omp_set_num_threads(static_cast<int>(state.range(0)));
  app::Simulation simulation = build_dam_break(spacing);
  for (int k = 0; k < warm_up_steps; ++k)
    step(*simulation.solver);
  for (auto _ : state)
    step(*simulation.solver);
  report(state, *simulation.store);
}

void configure(benchmark::internal::Benchmark* benchmark) {
  benchmark->ArgName("threads")->Arg(1)->Arg(2)->UseRealTime()->Unit(benchmark::kMillisecond);
}

BENCHMARK_CAPTURE(dam_break_3d, 25k, 0.025)->Apply(configure)->Iterations(200);
BENCHMARK_CAPTURE(dam_break_3d, 100k, 0.0135)->Apply(configure)->Iterations(60);
BENCHMARK_CAPTURE(dam_break_3d, 400k, 0.0075)->Apply(configure)->Iterations(20);

}  // namespace
}  // namespace partimix
