// MPM in the granular column collapse of seed 003 (cases/column_collapse_2d.yaml and
// cases/column_collapse.yaml; docs/performance.md, "MPM"): about 10,000 and 100,000 material
// points in 2D (plane strain) and in 3D (the seed's slice, widened for 100k), timed in the first
// steps of the collapse (after 20 warm-up steps).
#include "bench_support.hpp"

namespace partimix::bench {
namespace {

// 2D: 80 x 144 points (cell 2.5 mm), then 240 x 432 (cell 0.83 mm).
void mpm_2d_10k(benchmark::State& state) {
  time_steps(state, "column_collapse_2d", {"mpm.cell_size=0.0025", "mpm.fill[0].spacing=0.00125"});
}

void mpm_2d_100k(benchmark::State& state) {
  time_steps(state, "column_collapse_2d",
             {"mpm.cell_size=0.0008333333333333334", "mpm.fill[0].spacing=0.0004166666666666667"});
}

// 3D: the seed's 40 x 4 x 72 points (cell 5 mm), then 36 points deep.
void mpm_3d_10k(benchmark::State& state) {
  time_steps(state, "column_collapse", {"mpm.cell_size=0.005", "mpm.fill[0].spacing=0.0025"});
}

void mpm_3d_100k(benchmark::State& state) {
  time_steps(state, "column_collapse",
             {"mpm.cell_size=0.005", "mpm.fill[0].spacing=0.0025", "domain.max=[0.62,0.095,0.22]",
              "mpm.fill[0].region.max=[0.1,0.09,0.18]", "walls[4].point=[0,0.09,0]"});
}

BENCHMARK(mpm_2d_10k)->Apply(configure);
BENCHMARK(mpm_2d_100k)->Apply(configure);
BENCHMARK(mpm_3d_10k)->Apply(configure);
BENCHMARK(mpm_3d_100k)->Apply(configure);

}  // namespace
}  // namespace partimix::bench
