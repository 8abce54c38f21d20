// DEM in the rotating drum of seed 002 (cases/drum_seed.yaml, 30 rpm): 10,000 spheres of 2 mm in
// the seed's drum (200 x 50 mm), 10,000 prolate spheroids of the same volume, and 100,000
// spheres in a drum of 400 x 100 mm (fill 27%). The bed is
// inserted at random and settles for 0.3 s (10k) or 0.15 s (100k; a full settling takes
// minutes) before the timed steps; `contacts_per_grain` says how dense a bed was timed, and
// `solver_bytes_per_particle` adds the cell grid and the contact history to the store.
#include "bench_support.hpp"
#include "dem/dem_solver.hpp"

namespace partimix::bench {
namespace {

void report_contacts(benchmark::State& state, const app::Simulation& simulation) {
  const auto& solver = dynamic_cast<const dem::DemSolver&>(*simulation.methods[0].solver);
  state.counters["contacts_per_grain"] = solver.mean_contacts();
  state.counters["solver_bytes_per_particle"] =
      static_cast<double>(solver.bytes()) /
      static_cast<double>(simulation.methods[0].store->size());
}

void drum_10k(benchmark::State& state) {
  report_contacts(state, time_steps(state, "drum_seed", {"dem.fill.settle_time=0.3"}));
}

void drum_100k(benchmark::State& state) {
  report_contacts(state, time_steps(state, "drum_seed",
                                    {"dem.fill.settle_time=0.15", "dem.fill.count=100000",
                                     "walls[0].radius=0.2", "dem.fill.region.radius=0.2",
                                     "dem.fill.region.height=0.1", "domain.min=[-0.201,-0.201,0]",
                                     "domain.max=[0.201,0.201,0.1]"}));
}

// The same drum with 10,000 prolate spheroids of the same volume (sigma = 2,
// cases/drum_seed_ellipsoids.yaml): the cost of a superquadric particle-step against a sphere's.
void drum_ellipsoids_10k(benchmark::State& state) {
  report_contacts(state, time_steps(state, "drum_seed_ellipsoids", {"dem.fill.settle_time=0.3"}));
}

BENCHMARK(drum_10k)->Apply(configure);
BENCHMARK(drum_ellipsoids_10k)->Apply(configure);
BENCHMARK(drum_100k)->Apply(configure);

}  // namespace
}  // namespace partimix::bench
