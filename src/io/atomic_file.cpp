#include "io/atomic_file.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <string>
#include <system_error>

#include "core/error.hpp"

namespace partimix::io {
namespace {

std::filesystem::path temporary_path(const std::filesystem::path& file) {
  std::filesystem::path tmp = file;
  tmp += ".tmp";
  return tmp;
}

// Why the last system call failed (no space left on device, permission denied, ...): the
// streams set errno from the write or close that failed.
std::string reason() {
  return errno != 0 ? std::strerror(errno) : "an unknown I/O error";
}

void write_temporary(const std::filesystem::path& tmp, const std::filesystem::path& file,
                     const std::function<void(std::ostream&)>& write_content) {
  errno = 0;
  std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
  if (!out) {
    throw RunError("cannot open '" + tmp.string() + "' for writing '" + file.string() +
                   "': " + reason());
  }
  write_content(out);
  out.close();
  if (!out) {
    throw RunError("failed writing '" + file.string() + "': " + reason());
  }
}

}  // namespace

void replace_atomically(const std::filesystem::path& file,
                        const std::function<void(const std::filesystem::path&)>& write_temporary) {
  const std::filesystem::path tmp = temporary_path(file);
  std::error_code ignored;
  try {
    write_temporary(tmp);
  } catch (...) {
    std::filesystem::remove(tmp, ignored);
    throw;
  }
  std::error_code error;
  std::filesystem::rename(tmp, file, error);
  if (error) {
    std::filesystem::remove(tmp, ignored);
    throw RunError("cannot rename '" + tmp.string() + "' to '" + file.string() +
                   "': " + error.message());
  }
}

void write_atomically(const std::filesystem::path& file,
                      const std::function<void(std::ostream&)>& write_content) {
  replace_atomically(
      file, [&](const std::filesystem::path& tmp) { write_temporary(tmp, file, write_content); });
}

}  // namespace partimix::io
