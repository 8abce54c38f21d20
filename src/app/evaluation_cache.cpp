#include "app/evaluation_cache.hpp"

#include <fstream>

#include "core/error.hpp"
#include "io/atomic_file.hpp"

namespace partimix::app {

EvaluationCache::EvaluationCache(std::filesystem::path file, nlohmann::json search)
    : file_(std::move(file)), search_(std::move(search)) {
  if (!std::filesystem::exists(file_))
    return;
  nlohmann::json saved;
  try {
    std::ifstream in(file_);
    saved = nlohmann::json::parse(in);
    if (saved.at("search") != search_) {
      throw InputError({"--out", 0, 0, ""},
                       file_.parent_path().string() +
                           " holds another search (case, keys, figure or algorithm differ); "
                           "choose another folder with --out");
    }
    for (const nlohmann::json& item : saved.at("evaluations"))
      evaluations_.push_back({item.at("x").get<std::vector<double>>(),
                              item.at("run").get<std::string>(), item.at("value").get<double>()});
  } catch (const nlohmann::json::exception& error) {
    throw RunError("cannot read " + file_.string() + ": " + error.what());
  }
}

std::optional<Evaluation> EvaluationCache::find(const std::vector<double>& x) const {
  for (const Evaluation& evaluation : evaluations_)
    if (evaluation.x == x)
      return evaluation;
  return std::nullopt;
}

void EvaluationCache::add(const Evaluation& evaluation) {
  evaluations_.push_back(evaluation);
  save();
}

void EvaluationCache::save() const {
  nlohmann::json items = nlohmann::json::array();
  for (const Evaluation& evaluation : evaluations_)
    items.push_back({{"x", evaluation.x}, {"run", evaluation.run}, {"value", evaluation.value}});
  const nlohmann::json saved = {{"search", search_}, {"evaluations", items}};
  io::write_atomically(file_, [&](std::ostream& out) { out << saved.dump(2) << '\n'; });
}

}  // namespace partimix::app
