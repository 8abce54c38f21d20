#include "core/error.hpp"

#include <fmt/format.h>

namespace partimix {
namespace {

std::string describe(const InputLocation& where, const std::string& message) {
  std::string text = where.file.empty() ? std::string("<input>") : where.file;
  if (where.line > 0) {
    text += fmt::format(":{}:{}", where.line, where.column);
  }
  text += ": ";
  if (!where.key_path.empty()) {
    text += where.key_path + ": ";
  }
  return text + message;
}

}  // namespace

InputError::InputError(InputLocation location, const std::string& message)
    : std::runtime_error(describe(location, message)),
      location_(std::move(location)),
      message_(message) {}

}  // namespace partimix
