#pragma once
// Checkpoint files: a StateArchive saved as one HDF5 file, so that a run can be resumed
// (DESIGN.md, "One run"). Each entry is a dataset at its path, groups along the way: arrays as
// 2-D [rows, columns] datasets of little-endian 64-bit doubles or integers, texts as scalar
// fixed-length strings. The root group carries the attributes format = "partimix-checkpoint",
// format_version and partimix_version, and the first 512 bytes (HDF5's user block) a header
// with the file's length and checksum (io/checkpoint_header.hpp), checked before HDF5 reads
// anything.
#include <cstdint>
#include <filesystem>

#include "core/state_archive.hpp"

namespace partimix::io {

// Raised whenever the layout of the file changes; a file of another version is refused.
inline constexpr std::int64_t kCheckpointFormatVersion = 1;

// Writes archive to "<file>.tmp" and renames it over file, so that file is always either the
// previous checkpoint or the complete new one. Throws RunError naming file on any failure,
// after removing the temporary file.
void write_checkpoint(const std::filesystem::path& file, const StateArchive& archive);

// Reads back every entry, doubles bit for bit. A file that is missing, foreign, of another
// format_version, truncated or damaged throws InputError saying what is wrong; sizes are
// checked against the file's size before anything is allocated.
StateArchive read_checkpoint(const std::filesystem::path& file);

}  // namespace partimix::io
