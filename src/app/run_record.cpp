#include "app/run_record.hpp"

#include <fstream>

#include <nlohmann/json.hpp>

namespace partimix::app {
namespace {

const RunRecord kFailed{"failed", {}, {}};

std::string status_of(const nlohmann::json& run_json) {
  const nlohmann::json* status = nullptr;
  if (run_json.contains("run") && run_json["run"].is_object() &&
      run_json["run"].contains("status")) {
    status = &run_json["run"]["status"];
  }
  if (status == nullptr || !status->is_string() || *status == "running")
    return kFailed.status;
  return status->get<std::string>();
}

std::map<std::string, double> figures_of(const nlohmann::json& run_json) {
  std::map<std::string, double> figures;
  if (!run_json.contains("figures") || !run_json["figures"].is_object())
    return figures;
  for (const auto& [name, value] : run_json["figures"].items()) {
    if (value.is_number())
      figures[name] = value.get<double>();
  }
  return figures;
}

std::map<std::string, std::string> caveats_of(const nlohmann::json& run_json) {
  std::map<std::string, std::string> caveats;
  if (!run_json.contains("caveats") || !run_json["caveats"].is_object())
    return caveats;
  for (const auto& [name, reason] : run_json["caveats"].items()) {
    if (reason.is_string())
      caveats[name] = reason.get<std::string>();
  }
  return caveats;
}

}  // namespace

RunRecord read_run_record(const std::filesystem::path& run_dir) {
  std::ifstream in(run_dir / "run.json");
  if (!in)
    return kFailed;
  const nlohmann::json run_json = nlohmann::json::parse(in, nullptr, false);
  if (run_json.is_discarded() || !run_json.is_object())
    return kFailed;
  return {status_of(run_json), figures_of(run_json), caveats_of(run_json)};
}

}  // namespace partimix::app
