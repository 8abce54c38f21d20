#include "app/output_folder.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <set>
#include <system_error>
#include <vector>

#include <fmt/format.h>

#include "core/error.hpp"

namespace partimix::app {
namespace fs = std::filesystem;
namespace {

bool is_empty_folder(const fs::path& dir) {
  std::error_code error;
  return fs::is_empty(dir, error) && !error;
}

// The paths the manifest of `dir` lists that stay inside `dir` (no absolute path, no "..").
std::vector<fs::path> listed(const fs::path& dir) {
  std::ifstream in(dir / kManifestName);
  std::set<std::string> seen;
  std::vector<fs::path> paths;
  for (std::string line; std::getline(in, line);) {
    const fs::path relative = fs::path(line).lexically_normal();
    const bool inside = !line.empty() && relative.is_relative() && !relative.empty() &&
                        *relative.begin() != ".." && relative != ".";
    if (inside && seen.insert(relative.string()).second)
      paths.push_back(relative);
  }
  return paths;
}

// Removes what the manifest of `dir` lists: files, and folders once empty (a listed folder with
// a manifest of its own, a sweep's run, is cleared by that manifest first).
void clear_listed(const fs::path& dir, std::error_code& error) {
  std::vector<fs::path> folders;
  for (const fs::path& relative : listed(dir)) {
    const fs::path path = dir / relative;
    std::error_code missing;
    const fs::file_status status = fs::symlink_status(path, missing);
    if (fs::is_directory(status)) {
      folders.push_back(path);
      if (fs::exists(path / kManifestName, missing))
        clear_listed(path, error);
    } else if (fs::exists(status)) {
      fs::remove(path, error);
    }
    if (error)
      return;
  }
  // Deepest first, so that a folder's emptied subfolders go before it.
  std::sort(folders.begin(), folders.end(), [](const fs::path& a, const fs::path& b) {
    return std::distance(a.begin(), a.end()) > std::distance(b.begin(), b.end());
  });
  for (const fs::path& folder : folders) {
    fs::remove(folder / kManifestName, error);
    if (is_empty_folder(folder))
      fs::remove(folder, error);
    if (error)
      return;
  }
}

}  // namespace

void check_output_folder(const fs::path& dir, bool overwrite) {
  std::error_code error;
  if (!fs::exists(dir, error))
    return;
  if (!fs::is_directory(dir, error))
    throw InputError({dir.string(), 0, 0, "--out"}, "the output folder is a file");
  if (!overwrite && !fs::exists(dir / kManifestName, error) && !is_empty_folder(dir)) {
    throw InputError({dir.string(), 0, 0, "--out"},
                     "the output folder holds files that partimix did not write (it has no " +
                         std::string(kManifestName) +
                         "); choose another folder, or pass --overwrite to write into it "
                         "(nothing of yours is removed, files of the same name are replaced)");
  }
}

void prepare_output_folder(const fs::path& dir, bool overwrite) {
  check_output_folder(dir, overwrite);
  std::error_code error;
  if (fs::exists(dir / kManifestName, error))
    clear_listed(dir, error);
  if (!error)
    fs::create_directories(dir, error);
  if (!error) {
    std::ofstream manifest(dir / kManifestName, std::ios::trunc);
    if (!manifest)
      error = std::make_error_code(std::errc::permission_denied);
  }
  if (error) {
    throw RunError(
        fmt::format("cannot prepare the output folder {}: {}", dir.string(), error.message()));
  }
}

void record_output(const fs::path& dir, const std::string& relative) {
  std::ofstream manifest(dir / kManifestName, std::ios::app);
  manifest << relative << '\n';
  if (!manifest) {
    throw RunError(fmt::format("cannot write the list of outputs {}: {}",
                               (dir / kManifestName).string(), std::strerror(errno)));
  }
}

}  // namespace partimix::app
