#include "io/checkpoint_folder.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <string_view>
#include <system_error>
#include <utility>

#include "core/error.hpp"
#include "io/checkpoint_file.hpp"

namespace partimix::io {
namespace {

constexpr std::string_view kTemporarySuffix = ".tmp";

// The step of a checkpoint file name, or nothing for any other name. Only the name write()
// gives counts, so that "checkpoint_5.h5" copied in by hand cannot shadow a real one.
std::optional<std::uint64_t> step_of(const std::string& name) {
  constexpr std::string_view kPrefix = "checkpoint_";
  if (!name.starts_with(kPrefix)) {
    return std::nullopt;
  }
  std::uint64_t step = 0;
  const char* digits = name.data() + kPrefix.size();
  const auto [end, error] = std::from_chars(digits, name.data() + name.size(), step);
  if (error != std::errc() || name != CheckpointFolder::file_name(step)) {
    return std::nullopt;
  }
  return step;
}

bool is_leftover_temporary(const std::string& name) {
  return name.ends_with(kTemporarySuffix) &&
         step_of(name.substr(0, name.size() - kTemporarySuffix.size())).has_value();
}

void remove_file(const std::filesystem::path& file) {
  std::error_code error;
  std::filesystem::remove(file, error);
  if (error) {
    throw RunError("cannot remove old checkpoint file '" + file.string() + "': " + error.message());
  }
}

}  // namespace

std::string CheckpointFolder::file_name(std::uint64_t step) {
  return fmt::format("checkpoint_{:012}.h5", step);
}

std::filesystem::path CheckpointFolder::write(std::uint64_t step,
                                              const StateArchive& archive) const {
  std::error_code error;
  std::filesystem::create_directories(folder_, error);
  if (error) {
    throw RunError("cannot create the checkpoint folder '" + folder_.string() +
                   "': " + error.message());
  }
  const std::filesystem::path file = folder_ / file_name(step);
  write_checkpoint(file, archive);
  remove_old_files();
  return file;
}

void CheckpointFolder::remove_old_files() const {
  const std::vector<Checkpoint> found = checkpoints();
  for (std::size_t i = 2; i < found.size(); ++i) {
    remove_file(found[i].file);
  }
  std::error_code error;
  for (const auto& item : std::filesystem::directory_iterator(folder_, error)) {
    if (is_leftover_temporary(item.path().filename().string())) {
      remove_file(item.path());
    }
  }
}

void CheckpointFolder::remove_newer_than(const std::filesystem::path& used) const {
  const std::optional<std::uint64_t> used_step = step_of(used.filename().string());
  for (const Checkpoint& checkpoint : checkpoints()) {
    if (used_step && checkpoint.step > *used_step)
      remove_file(checkpoint.file);
  }
}

std::vector<CheckpointFolder::Checkpoint> CheckpointFolder::checkpoints() const {
  std::vector<Checkpoint> found;
  std::error_code error;
  for (const auto& item : std::filesystem::directory_iterator(folder_, error)) {
    const std::optional<std::uint64_t> step = step_of(item.path().filename().string());
    if (step && item.is_regular_file(error)) {
      found.push_back({*step, item.path()});
    }
  }
  std::sort(found.begin(), found.end(),
            [](const Checkpoint& a, const Checkpoint& b) { return a.step > b.step; });
  return found;
}

std::optional<std::filesystem::path> CheckpointFolder::latest() const {
  const std::vector<Checkpoint> found = checkpoints();
  if (found.empty()) {
    return std::nullopt;
  }
  return found.front().file;
}

StateArchive CheckpointFolder::read_latest(std::filesystem::path* used) const {
  const std::vector<Checkpoint> found = checkpoints();
  if (found.empty()) {
    std::error_code ignored;
    throw InputError(InputLocation{folder_.string(), 0, 0, ""},
                     std::filesystem::is_directory(folder_, ignored)
                         ? "no checkpoint (checkpoint_<step>.h5) in the folder"
                         : "no checkpoint: the folder does not exist");
  }
  std::optional<InputError> newest_error;
  for (const Checkpoint& checkpoint : found) {
    try {
      StateArchive archive = read_checkpoint(checkpoint.file);
      if (used != nullptr) {
        *used = checkpoint.file;
      }
      return archive;
    } catch (const InputError& error) {
      if (!newest_error) {
        newest_error = error;
      }
    }
  }
  throw *newest_error;
}

}  // namespace partimix::io
