#pragma once
// Run-time selection by name (DESIGN.md, "One run"): each model registers a factory under a
// name; case files choose the model by that name. Adding a model is one file plus one line.
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace partimix {

template <class Base, class... Args>
class Registry {
 public:
  using Factory = std::function<std::unique_ptr<Base>(Args...)>;

  void add(const std::string& name, Factory factory) { factories_[name] = std::move(factory); }

  bool contains(const std::string& name) const { return factories_.count(name) > 0; }

  // Returns nullptr when the name is unknown; callers turn that into an InputError.
  std::unique_ptr<Base> create(const std::string& name, Args... args) const {
    auto found = factories_.find(name);
    if (found == factories_.end()) {
      return nullptr;
    }
    return found->second(std::forward<Args>(args)...);
  }

  std::vector<std::string> names() const {
    std::vector<std::string> result;
    for (const auto& entry : factories_) {
      result.push_back(entry.first);
    }
    return result;
  }

 private:
  std::map<std::string, Factory> factories_;
};

}  // namespace partimix
