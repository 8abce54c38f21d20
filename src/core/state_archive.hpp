#pragma once
// Everything a run must save to be resumed (DESIGN.md, "One run": particles, contact
// histories, bodies, time, random numbers, analysis histories), as named arrays in memory. Each
// method and analysis puts its state under its own path ("methods/sph/fields/position") and
// gets it back on resume; io/checkpoint_file turns the archive into an HDF5 file and back, so
// that no method knows the file format.
#include <cstddef>
#include <cstdint>
#include <map>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/vec.hpp"

namespace partimix {

// Asked for an entry that is not in the archive, or that has another kind or shape: the saved
// state does not fit the run that reads it. The message names the path, what was expected and
// what was found.
class StateError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class StateArchive {
 public:
  enum class Kind { doubles, integers, text };

  // One entry: a row-major rows x columns array of doubles or integers, or a text. Only the
  // member of its kind is filled; columns is 1 for a text.
  struct Entry {
    Kind kind = Kind::doubles;
    std::size_t columns = 1;
    std::vector<double> doubles;
    std::vector<std::int64_t> integers;
    std::string text;

    std::size_t rows() const;
  };

  // A path is segments joined by '/', each non-empty, made of [A-Za-z0-9_.+-] and neither "."
  // nor ".."; an entry's path cannot also lead to other entries ("a/b" and "a/b/c"), since in
  // the file it is either a dataset or a group. A bad path, columns == 0 or a size that is not
  // a multiple of columns throw std::invalid_argument. Putting a path again replaces it.
  void put_doubles(const std::string& path, std::span<const double> values,
                   std::size_t columns = 1);
  void put_integers(const std::string& path, std::span<const std::int64_t> values,
                    std::size_t columns = 1);
  void put_text(const std::string& path, std::string text);
  void put_scalar(const std::string& path, double value);  // a 1 x 1 array of doubles
  void put_vectors(const std::string& path, std::span<const Vec3> values);  // n x 3 doubles

  // Each getter throws StateError when the path is missing, holds another kind, or has another
  // number of columns (scalar: not 1 x 1; vectors: not 3 columns).
  std::span<const double> doubles(const std::string& path, std::size_t columns = 1) const;
  std::span<const std::int64_t> integers(const std::string& path, std::size_t columns = 1) const;
  const std::string& text(const std::string& path) const;
  double scalar(const std::string& path) const;
  std::vector<Vec3> vectors(const std::string& path) const;

  bool contains(const std::string& path) const { return entries_.count(path) > 0; }
  std::vector<std::string> paths() const;  // sorted
  // Every entry by path, sorted: what a writer walks.
  const std::map<std::string, Entry>& entries() const { return entries_; }

  static bool is_valid_path(const std::string& path);

 private:
  void put(const std::string& path, Entry entry);
  const Entry& find(const std::string& path, Kind kind, std::size_t columns) const;

  std::map<std::string, Entry> entries_;
};

}  // namespace partimix
