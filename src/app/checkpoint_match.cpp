#include "app/checkpoint_match.hpp"

#include <string>

#include <fmt/format.h>

#include "core/error.hpp"

namespace partimix::app {
namespace {

const std::vector<std::string> kMayChange{"/time/end", "/time/checkpoint_interval", "/description"};

// "/walls/0/motion/rpm" as the case's key path "walls[0].motion.rpm".
std::string key_path(const std::string& pointer) {
  std::string path;
  std::size_t begin = 1;
  while (begin <= pointer.size()) {
    std::size_t end = pointer.find('/', begin);
    if (end == std::string::npos)
      end = pointer.size();
    const std::string token = pointer.substr(begin, end - begin);
    const bool index = !token.empty() && token.find_first_not_of("0123456789") == std::string::npos;
    path += index ? "[" + token + "]" : (path.empty() ? "" : ".") + token;
    begin = end + 1;
  }
  return path;
}

std::string value_at(const nlohmann::json& document, const std::string& pointer) {
  const nlohmann::json::json_pointer at(pointer);
  return document.contains(at) ? document.at(at).dump() : "absent";
}

}  // namespace

void check_checkpoint_matches(const io::Case& the_case, const StateArchive& checkpoint,
                              const std::filesystem::path& file) {
  auto refuse = [&](const std::string& key, const std::string& what) {
    return InputError(InputLocation{file.string(), 0, 0, key}, what);
  };
  nlohmann::json saved;
  try {
    saved = nlohmann::json::parse(checkpoint.text("case/resolved"));
  } catch (const std::exception& error) {
    throw refuse("case/resolved",
                 fmt::format("not a case this version can read: {}", error.what()));
  }
  for (const nlohmann::json& change : nlohmann::json::diff(saved, the_case.resolved)) {
    const std::string pointer = change.at("path").get<std::string>();
    const bool may_change = std::any_of(kMayChange.begin(), kMayChange.end(),
                                        [&](const std::string& p) { return pointer == p; });
    if (may_change)
      continue;
    throw refuse(key_path(pointer),
                 fmt::format("the checkpoint was written with {} = {}, the case now has {}; a "
                             "run resumes only the case it was (only time.end, "
                             "time.checkpoint_interval and description may change)",
                             key_path(pointer), value_at(saved, pointer),
                             value_at(the_case.resolved, pointer)));
  }
}

}  // namespace partimix::app
