#pragma once
// Grains placed by the user (docs/case-reference.md, "dem.grains"), in place of a random fill:
// a list in the case (`dem.grains`) or a CSV file (`dem.grains_file`), each grain with its
// position, radius and species and, optionally, its velocity and angular velocity. They start as
// given, without settling, so that an impact or a spin can be set up exactly.
#include <filesystem>
#include <string>
#include <vector>

#include "dem/config.hpp"
#include "io/size_limits.hpp"
#include "io/yaml_reader.hpp"

namespace partimix::dem {

// The grains of `dem.grains` (a list of maps) in the section `dem`. Throws InputError at the key.
Grains read_grain_list(io::Reader& dem, const std::vector<Species>& species,
                       const io::SizeLimits& limits);

// The grains of the CSV file at `path`: a header naming the columns (x, y, z, radius required;
// vx, vy, vz, wx, wy, wz and species, a name or an index, optional; in any order), then one
// grain per line; blank lines and lines starting with '#' are skipped. Throws InputError naming
// the file, line and column.
Grains read_grain_file(const std::filesystem::path& path, const std::vector<Species>& species,
                       const io::SizeLimits& limits);

}  // namespace partimix::dem
