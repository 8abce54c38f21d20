#pragma once
// The first 512 bytes of a checkpoint file: HDF5's user block, which HDF5 reserves for the
// application and skips. partimix writes there, as a few lines of text, the format name and
// version, the file's length and a checksum of the rest of the file, and checks them before
// HDF5 parses anything. HDF5 does not checksum raw data and its parser is not hardened against
// damaged files, so a truncated, bit-flipped or foreign file is refused here with a clear
// message, and HDF5 only ever reads files that are byte for byte what partimix wrote.
#include <cstddef>
#include <cstdint>
#include <filesystem>

namespace partimix::io::checkpoint_header {

// The user block size; the HDF5 file must be created with H5Pset_userblock(fcpl, kBytes).
inline constexpr std::size_t kBytes = 512;
inline constexpr char kFormatName[] = "partimix-checkpoint";

// Fills the user block of the closed HDF5 file `file` with the header for its current
// content. Throws RunError naming `reported_as` (the checkpoint that `file` will become).
void stamp(const std::filesystem::path& file, std::int64_t format_version,
           const std::filesystem::path& reported_as);

// Checks that `file` starts with a header of `format_version` and that its length and
// checksum match it. Throws InputError saying what is wrong; returns the file's size.
std::uintmax_t verify(const std::filesystem::path& file, std::int64_t format_version);

}  // namespace partimix::io::checkpoint_header
