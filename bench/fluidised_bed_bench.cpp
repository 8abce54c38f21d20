// CFD-DEM in the fluidised bed of cases/cfdem_fluidised_bed.yaml (docs/performance.md,
// "CFD-DEM"), widened to about 10,000 and 100,000 grains of 1 mm on the same 2 mm cells: the
// grains placed at random in the lower 20 mm and settled for 0.08 s (DEM alone, untimed; they
// fall into a bed about 10 mm deep), water entering at 12 mm/s. One
// iteration is one coupled step: the coupling's work before the fluid (mapping the grains, the
// drag, the fluid's sources), the fluid's step, the coupling's work before the grains (gathering
// the fluid's new state), and the grains' 200 sub-steps; each part's milliseconds per coupled step
// are counters.
#include <chrono>

#include "bench_support.hpp"
#include "coupling/coupling.hpp"

namespace partimix::bench {
namespace {

using Clock = std::chrono::steady_clock;

double milliseconds(Clock::time_point from, Clock::time_point to) {
  return std::chrono::duration<double, std::milli>(to - from).count();
}

void fluidised_bed(benchmark::State& state, double side, int grains) {
  omp_set_num_threads(static_cast<int>(state.range(0)));
  const std::string width = std::to_string(side);
  const io::Case the_case =
      io::load_case(std::string(PARTIMIX_SOURCE_DIR) + "/cases/cfdem_fluidised_bed.yaml",
                    {"domain.max=[" + width + ", " + width + ", 0.04]",
                     "dem.fill.count=" + std::to_string(grains),
                     "dem.fill.region.max=[" + width + ", " + width + ", 0.02]",
                     "dem.fill.settle_time=0.08", "dem.fill.settle_energy=1e-15"});
  app::Simulation simulation = app::build_simulation(the_case);
  Solver& fluid = *simulation.methods[0].solver;
  Solver& dem = *simulation.methods[1].solver;
  coupling::Coupling& coupling = *simulation.couplings[0];
  const int sub_steps = the_case.methods[1].sub_steps;
  const double dt = fluid.stable_dt();
  double coupling_ms = 0.0;
  double fluid_ms = 0.0;
  double dem_ms = 0.0;
  double t = 0.0;
  auto coupled_step = [&](bool timed) {
    const auto start = Clock::now();
    coupling.before_method(0, t, dt);
    const auto mapped = Clock::now();
    fluid.step(dt);
    const auto stepped = Clock::now();
    coupling.before_method(1, t, dt);
    const auto gathered = Clock::now();
    for (int s = 0; s < sub_steps; ++s)
      dem.step(dt / sub_steps);
    const auto end = Clock::now();
    t += dt;
    if (timed) {
      coupling_ms += milliseconds(start, mapped) + milliseconds(stepped, gathered);
      fluid_ms += milliseconds(mapped, stepped);
      dem_ms += milliseconds(gathered, end);
    }
  };
  for (int k = 0; k < 2; ++k)
    coupled_step(false);
  for (auto _ : state)
    coupled_step(true);
  const auto steps = static_cast<double>(state.iterations());
  state.counters["coupling_ms"] = coupling_ms / steps;
  state.counters["fluid_ms"] = fluid_ms / steps;
  state.counters["dem_ms"] = dem_ms / steps;
  state.counters["cells"] = static_cast<double>(simulation.methods[0].store->size());
  state.counters["grains"] = static_cast<double>(simulation.methods[1].store->size());
  state.counters["grain_steps_per_s"] = benchmark::Counter(
      steps * sub_steps * static_cast<double>(grains), benchmark::Counter::kIsRate);
}

// 30 x 30 mm and 95 x 95 mm across: a bed about 10 mm deep.
void cfd_dem_10k(benchmark::State& state) {
  fluidised_bed(state, 0.03, 10000);
}

void cfd_dem_100k(benchmark::State& state) {
  fluidised_bed(state, 0.095, 100000);
}

BENCHMARK(cfd_dem_10k)->Apply(configure)->Iterations(5);
BENCHMARK(cfd_dem_100k)->Apply(configure)->Iterations(2);

}  // namespace
}  // namespace partimix::bench
