#include "dem/grain_list.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <system_error>

#include <fmt/format.h>

#include "core/error.hpp"

namespace partimix::dem {
namespace {

using io::kPositive;

// The species index of `name`: a species name or its index.
std::optional<int> species_of(const std::string& name, const std::vector<Species>& species) {
  for (std::size_t s = 0; s < species.size(); ++s) {
    if (species[s].name == name || std::to_string(s) == name)
      return static_cast<int>(s);
  }
  return std::nullopt;
}

std::string species_names(const std::vector<Species>& species) {
  std::string names;
  for (const Species& s : species)
    names += (names.empty() ? "" : ", ") + s.name;
  return names;
}

void add_grain(Grains& grains, const Vec3& x, double r, const Vec3& v, const Vec3& w, int s) {
  grains.position.push_back(x);
  grains.radius.push_back(r);
  grains.velocity.push_back(v);
  grains.angular_velocity.push_back(w);
  grains.species.push_back(s);
}

const std::array<std::string, 11> kColumns{"x",  "y",  "z",  "radius", "vx",     "vy",
                                           "vz", "wx", "wy", "wz",     "species"};

// Splits a CSV line at commas, trimming blanks around each cell.
std::vector<std::string> cells_of(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream in(line);
  for (std::string cell; std::getline(in, cell, ',');) {
    const auto first = cell.find_first_not_of(" \t\r");
    const auto last = cell.find_last_not_of(" \t\r");
    cells.push_back(first == std::string::npos ? "" : cell.substr(first, last - first + 1));
  }
  if (!line.empty() && line.back() == ',')
    cells.emplace_back();
  return cells;
}

class GrainFile {
 public:
  GrainFile(std::filesystem::path path, const std::vector<Species>& species)
      : path_(std::move(path)), species_(species) {}

  // Only a regular file: a folder or a device (/dev/zero, which has no line end) is refused.
  Grains read(const io::SizeLimits& limits) {
    std::error_code ignored;
    std::ifstream in(path_);
    if (!std::filesystem::is_regular_file(path_, ignored) || !in)
      throw error(0, "cannot read the grain file: no such readable regular file");
    Grains grains;
    bool header = true;
    for (std::string line; std::getline(in, line);) {
      ++line_;
      if (line.find_first_not_of(" \t\r") == std::string::npos || line.front() == '#')
        continue;
      if (header) {
        read_header(cells_of(line));
        header = false;
        continue;
      }
      if (static_cast<double>(grains.position.size()) >= limits.particles)
        throw error(0, fmt::format("more than limits.particles = {:.3g} grains", limits.particles));
      read_grain(cells_of(line), grains);
    }
    if (grains.position.empty())
      throw error(0, "the grain file holds no grain");
    return grains;
  }

 private:
  InputError error(int column, const std::string& message) const {
    return InputError({path_.string(), line_, column, ""}, message);
  }

  void read_header(const std::vector<std::string>& names) {
    for (std::size_t c = 0; c < names.size(); ++c) {
      if (std::find(kColumns.begin(), kColumns.end(), names[c]) == kColumns.end()) {
        throw error(0, fmt::format("unknown column '{}'; expected x, y, z, radius and optionally "
                                   "vx, vy, vz, wx, wy, wz, species",
                                   names[c]));
      }
      if (!index_.emplace(names[c], c).second)
        throw error(0, fmt::format("the column '{}' appears twice", names[c]));
    }
    for (const char* required : {"x", "y", "z", "radius"}) {
      if (!index_.contains(required))
        throw error(0, fmt::format("the header lacks the column '{}'", required));
    }
    columns_ = names.size();
  }

  double number(const std::vector<std::string>& cells, const std::string& name) const {
    const auto at = index_.find(name);
    if (at == index_.end())
      return 0.0;
    const std::string& text = cells[at->second];
    double value = 0.0;
    const auto [end, status] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (status != std::errc() || end != text.data() + text.size() || !std::isfinite(value)) {
      throw error(static_cast<int>(at->second) + 1,
                  fmt::format("{}: expected a finite number, got '{}'", name, text));
    }
    return value;
  }

  void read_grain(const std::vector<std::string>& cells, Grains& grains) const {
    if (cells.size() != columns_)
      throw error(0, fmt::format("{} cells for {} columns", cells.size(), columns_));
    const double radius = number(cells, "radius");
    if (!(radius > 0.0))
      throw error(static_cast<int>(index_.at("radius")) + 1, "radius: must be > 0");
    int s = 0;
    if (const auto at = index_.find("species"); at != index_.end()) {
      const auto found = species_of(cells[at->second], species_);
      if (!found) {
        throw error(static_cast<int>(at->second) + 1,
                    fmt::format("species: '{}' is none of: {}", cells[at->second],
                                species_names(species_)));
      }
      s = *found;
    }
    if (species_[s].shape) {
      throw error(0, fmt::format("species {}: superquadric grains are placed by fill or by the "
                                 "grains list, not from a CSV file (yet)",
                                 species_[s].name));
    }
    add_grain(grains, Vec3(number(cells, "x"), number(cells, "y"), number(cells, "z")), radius,
              Vec3(number(cells, "vx"), number(cells, "vy"), number(cells, "vz")),
              Vec3(number(cells, "wx"), number(cells, "wy"), number(cells, "wz")), s);
  }

  std::filesystem::path path_;
  const std::vector<Species>& species_;
  std::map<std::string, std::size_t> index_;
  std::size_t columns_ = 0;
  int line_ = 0;
};

}  // namespace

Grains read_grain_list(io::Reader& dem, const std::vector<Species>& species,
                       const io::SizeLimits& limits) {
  Grains grains;
  std::vector<std::string> names;
  for (const Species& s : species)
    names.push_back(s.name);
  std::vector<io::Reader> items = dem.list("grains");
  if (static_cast<double>(items.size()) > limits.particles) {
    throw dem.error("grains", fmt::format("{} grains are more than limits.particles = {:.3g}",
                                          items.size(), limits.particles));
  }
  for (io::Reader& item : items) {
    const Vec3 x = item.vector("position", 3);
    const std::string name = item.choice("species", names.front(), names);
    const int s = *species_of(name, species);
    const bool shaped = species[s].shape.has_value();
    if (shaped && item.contains("radius"))
      throw item.error("radius", "a superquadric takes its size from species[].shape");
    const double r =
        shaped ? species[s].shape->bounding_radius() : item.required<double>("radius", kPositive);
    const Vec3 v = item.vector("velocity", 3, Vec3::Zero());
    const Vec3 w = item.vector("angular_velocity", 3, Vec3::Zero());
    item.done();
    add_grain(grains, x, r, v, w, s);
  }
  return grains;
}

Grains read_grain_file(const std::filesystem::path& path, const std::vector<Species>& species,
                       const io::SizeLimits& limits) {
  return GrainFile(path, species).read(limits);
}

}  // namespace partimix::dem
