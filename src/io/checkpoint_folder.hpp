#pragma once
// The checkpoints of one run: a folder (OUTDIR/checkpoints) of checkpoint_<step>.h5 files, of
// which the newest two are kept. Resuming reads the newest one that reads without error, so a
// checkpoint damaged after it was written (disk full, a copy cut short) still leaves the one
// before it.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/state_archive.hpp"

namespace partimix::io {

class CheckpointFolder {
 public:
  explicit CheckpointFolder(std::filesystem::path folder) : folder_(std::move(folder)) {}

  const std::filesystem::path& path() const { return folder_; }

  // Writes checkpoint_<step, 12 digits>.h5 (creating the folder if needed) through
  // write_checkpoint, then removes every checkpoint but the newest two by step, and any
  // temporary file an interrupted write left. Returns the file written; throws RunError.
  std::filesystem::path write(std::uint64_t step, const StateArchive& archive) const;

  // The checkpoint with the largest step, whether or not it reads; none in an empty or
  // missing folder.
  std::optional<std::filesystem::path> latest() const;

  // Reads the newest checkpoint that reads without error, trying older ones in turn, and sets
  // *used to its file. Throws InputError: the newest one's when none reads, or one saying the
  // folder holds no checkpoint.
  StateArchive read_latest(std::filesystem::path* used = nullptr) const;

  // Removes the checkpoints newer than `used` (damaged ones read_latest passed over), so that
  // the resumed run's own checkpoints are the newest and the pruning keeps them.
  void remove_newer_than(const std::filesystem::path& used) const;

  static std::string file_name(std::uint64_t step);

 private:
  struct Checkpoint {
    std::uint64_t step;
    std::filesystem::path file;
  };
  std::vector<Checkpoint> checkpoints() const;  // newest first
  void remove_old_files() const;

  std::filesystem::path folder_;
};

}  // namespace partimix::io
