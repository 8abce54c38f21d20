#pragma once
// Writes a whole file so that a reader sees either the previous content or the complete new
// one, never a half-written file (DESIGN.md, "Inputs, outputs, errors": a failed run keeps the
// last good frame). The content goes to "<file>.tmp", which is then renamed over the file.
#include <filesystem>
#include <functional>
#include <ostream>

namespace partimix::io {

// Calls write_content with a binary stream on "<file>.tmp", then renames it to file. Any I/O
// failure removes the temporary file and throws RunError naming file.
void write_atomically(const std::filesystem::path& file,
                      const std::function<void(std::ostream&)>& write_content);

// The same for a writer that makes the file itself: write_temporary(tmp) writes "<file>.tmp"
// (a library that opens files by name, such as HDF5), which is then renamed to file.
void replace_atomically(const std::filesystem::path& file,
                        const std::function<void(const std::filesystem::path&)>& write_temporary);

}  // namespace partimix::io
