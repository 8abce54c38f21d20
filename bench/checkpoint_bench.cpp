// Cost of a checkpoint (docs/architecture-notes.md, "Checkpoints"): gathering a method's state
// into the archive and writing the HDF5 file (write), and reading it back and restoring the
// method (read), for the 3D dam break (SPH, 100k and 400k particles) and the seed's drum (DEM,
// 10k grains with their contact histories). Reported: file bytes per particle and the rate in
// MB/s of the file written or read. The file goes to the temporary folder.
#include <filesystem>

#include <unistd.h>

#include "bench_support.hpp"
#include "io/checkpoint_file.hpp"

namespace partimix::bench {
namespace {

std::filesystem::path checkpoint_path() {
  return std::filesystem::temp_directory_path() /
         ("partimix_checkpoint_bench_" + std::to_string(::getpid()) + ".h5");
}

void report_file(benchmark::State& state, const std::filesystem::path& file,
                 std::size_t particles) {
  const auto bytes = static_cast<double>(std::filesystem::file_size(file));
  state.counters["file_bytes_per_particle"] = bytes / static_cast<double>(particles);
  state.counters["MB_per_s"] = benchmark::Counter(
      bytes * 1e-6 * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

void checkpoint_write(benchmark::State& state, const std::string& case_name,
                      const std::vector<std::string>& overrides) {
  const std::string path = std::string(PARTIMIX_SOURCE_DIR) + "/cases/" + case_name + ".yaml";
  app::Simulation simulation = app::build_simulation(io::load_case(path, overrides));
  const Solver& solver = *simulation.methods[0].solver;
  const auto file = checkpoint_path();
  for (auto _ : state) {
    StateArchive archive;
    solver.save(archive, "methods/m/");
    io::write_checkpoint(file, archive);
  }
  report_file(state, file, simulation.particle_count());
  std::filesystem::remove(file);
}

void checkpoint_read(benchmark::State& state, const std::string& case_name,
                     const std::vector<std::string>& overrides) {
  const std::string path = std::string(PARTIMIX_SOURCE_DIR) + "/cases/" + case_name + ".yaml";
  app::Simulation simulation = app::build_simulation(io::load_case(path, overrides));
  Solver& solver = *simulation.methods[0].solver;
  const auto file = checkpoint_path();
  StateArchive saved;
  solver.save(saved, "methods/m/");
  io::write_checkpoint(file, saved);
  for (auto _ : state)
    solver.restore(io::read_checkpoint(file), "methods/m/");
  report_file(state, file, simulation.particle_count());
  std::filesystem::remove(file);
}

const std::vector<std::string> kDam100k{"sph.spacing=0.0135"};
const std::vector<std::string> kDam400k{"sph.spacing=0.0075"};
const std::vector<std::string> kDrum10k{"dem.fill.settle_time=0.3"};

BENCHMARK_CAPTURE(checkpoint_write, dam_break_100k, "dam_break_3d", kDam100k)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(10);
BENCHMARK_CAPTURE(checkpoint_read, dam_break_100k, "dam_break_3d", kDam100k)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(10);
BENCHMARK_CAPTURE(checkpoint_write, dam_break_400k, "dam_break_3d", kDam400k)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(5);
BENCHMARK_CAPTURE(checkpoint_read, dam_break_400k, "dam_break_3d", kDam400k)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(5);
BENCHMARK_CAPTURE(checkpoint_write, drum_10k, "drum_seed", kDrum10k)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(20);
BENCHMARK_CAPTURE(checkpoint_read, drum_10k, "drum_seed", kDrum10k)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(20);

}  // namespace
}  // namespace partimix::bench
