#pragma once
// What every benchmark of bench/ does (docs/performance.md, "What is measured"): build a case of
// cases/ at a given spacing, take warm-up steps untimed, time one solver step per iteration,
// and report particle-steps per second, the particle counts and the bytes per particle.
//
// peak_rss_bytes_per_particle divides the peak resident set of the whole process so far by the
// particles of this benchmark, so each file registers its sizes smallest first and `make bench`
// runs each family in its own process: each figure is then the peak of its own size (or of an
// equal one), not of a larger run before it.
#include <benchmark/benchmark.h>
#include <omp.h>
#include <sys/resource.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "app/simulation.hpp"
#include "io/case.hpp"
#include "particles/particle_store.hpp"
#include "particles/solver.hpp"

namespace partimix::bench {

inline void step(Solver& solver) {
  solver.step(solver.stable_dt());
}

inline double peak_rss_bytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) * 1024.0;  // ru_maxrss is in KiB on Linux
}

inline void report(benchmark::State& state, const ParticleStore& store) {
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

constexpr int warm_up_steps = 20;

// state.range(0): the number of OpenMP threads; case_name: a file of cases/ without ".yaml",
// built with `overrides` (as --set). Returns the simulation after the timed steps.
inline app::Simulation time_steps(benchmark::State& state, const std::string& case_name,
                                  const std::vector<std::string>& overrides) {
  omp_set_num_threads(static_cast<int>(state.range(0)));
  const std::string path = std::string(PARTIMIX_SOURCE_DIR) + "/cases/" + case_name + ".yaml";
  app::Simulation simulation = app::build_simulation(io::load_case(path, overrides));
  for (int k = 0; k < warm_up_steps; ++k)
    step(*simulation.methods[0].solver);
  for (auto _ : state)
    step(*simulation.methods[0].solver);
  report(state, *simulation.methods[0].store);
  return simulation;
}

inline void time_steps(benchmark::State& state, const std::string& case_name, double spacing) {
  time_steps(state, case_name, {"sph.spacing=" + std::to_string(spacing)});
}

inline void configure(benchmark::internal::Benchmark* benchmark) {
  benchmark->ArgName("threads")->Arg(1)->Arg(2)->UseRealTime()->Unit(benchmark::kMillisecond);
}

}  // namespace partimix::bench
