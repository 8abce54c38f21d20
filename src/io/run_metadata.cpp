#include "io/run_metadata.hpp"

#include <ostream>

#include "io/atomic_file.hpp"

namespace partimix::io {

nlohmann::json to_json(const RunSummary& summary) {
  const double particle_steps =
      static_cast<double>(summary.particles) * static_cast<double>(summary.steps);
  const double rate = summary.wall_seconds > 0.0 ? particle_steps / summary.wall_seconds : 0.0;
  return {{"status", summary.status},
          {"message", summary.message},
          {"particles", summary.particles},
          {"steps", summary.steps},
          {"simulated_time", summary.simulated_time},
          {"wall_seconds", summary.wall_seconds},
          {"threads", summary.threads},
          {"particle_steps_per_second", rate}};
}

void write_run_json(const std::filesystem::path& file, const nlohmann::json& content) {
  // Invalid UTF-8 (say, in a failure message quoting a file name) is replaced, not fatal.
  const std::string text =
      content.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
  write_atomically(file, [&text](std::ostream& out) { out << text; });
}

}  // namespace partimix::io
