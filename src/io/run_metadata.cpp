#include "io/run_metadata.hpp"

#include <ostream>

#include "io/atomic_file.hpp"

namespace partimix::io {
namespace {

double particle_steps_per_second(std::size_t particles, std::size_t steps, double seconds) {
  const double particle_steps = static_cast<double>(particles) * static_cast<double>(steps);
  return seconds > 0.0 ? particle_steps / seconds : 0.0;
}

}  // namespace

nlohmann::json to_json(const RunSummary& summary) {
  return {{"status", summary.status},
          {"message", summary.message},
          {"particles", summary.particles},
          {"steps", summary.steps},
          {"simulated_time", summary.simulated_time},
          {"wall_seconds", summary.wall_seconds},
          {"threads", summary.threads},
          {"particle_steps_per_second",
           particle_steps_per_second(summary.particles, summary.steps, summary.wall_seconds)},
          {"process_steps", summary.process_steps},
          {"process_wall_seconds", summary.process_wall_seconds},
          {"process_particle_steps_per_second",
           particle_steps_per_second(summary.particles, summary.process_steps,
                                     summary.process_wall_seconds)}};
}

void write_run_json(const std::filesystem::path& file, const nlohmann::json& content) {
  // Invalid UTF-8 (say, in a failure message quoting a file name) is replaced, not fatal.
  const std::string text =
      content.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
  write_atomically(file, [&text](std::ostream& out) { out << text; });
}

}  // namespace partimix::io
