#include "app/run_record.hpp"

#include <fstream>

#include <nlohmann/json.hpp>

namespace partimix::app {
namespace {

const RunRecord kFailed{"failed", {}, {}, {}};

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

// The strings of the object `key` of run.json, by name (caveats, figure units).
std::map<std::string, std::string> texts_of(const nlohmann::json& run_json,
                                            const std::string& key) {
  std::map<std::string, std::string> texts;
  if (!run_json.contains(key) || !run_json[key].is_object())
    return texts;
  for (const auto& [name, text] : run_json[key].items()) {
    if (text.is_string())
      texts[name] = text.get<std::string>();
  }
  return texts;
}

}  // namespace

RunRecord read_run_record(const std::filesystem::path& run_dir) {
  std::ifstream in(run_dir / "run.json");
  if (!in)
    return kFailed;
  const nlohmann::json run_json = nlohmann::json::parse(in, nullptr, false);
  if (run_json.is_discarded() || !run_json.is_object())
    return kFailed;
  return {status_of(run_json), figures_of(run_json), texts_of(run_json, "caveats"),
          texts_of(run_json, "figure_units")};
}

}  // namespace partimix::app
