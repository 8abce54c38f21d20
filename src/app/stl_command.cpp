// `partimix stl`: the walls generated as meshes (a truck drum), as binary STL files to check in
// ParaView or a CAD viewer (docs/truck-drum.md, "Meshes and the STL export").
#include <fmt/format.h>

#include "app/commands.hpp"
#include "core/error.hpp"
#include "geometry/truck_drum_mesh.hpp"
#include "io/atomic_file.hpp"
#include "io/case.hpp"

namespace partimix::app {

int stl_command(const std::string& case_file, const std::vector<std::string>& overrides,
                const std::filesystem::path& output_dir) {
  try {
    const io::Case the_case = io::load_case(case_file, overrides);
    int written = 0;
    for (std::size_t k = 0; k < the_case.walls.size(); ++k) {
      const std::shared_ptr<const geometry::Shape>& shape = the_case.walls[k].shape;
      const geometry::TriangleSoup triangles =
          shape ? shape->triangles() : geometry::TriangleSoup{};
      if (triangles.empty())
        continue;
      std::filesystem::create_directories(output_dir);
      const std::filesystem::path file = output_dir / fmt::format("wall_{}.stl", k);
      io::write_atomically(file, [&](std::ostream& out) { geometry::write_stl(out, triangles); });
      fmt::print(stderr, "walls[{}]: {} triangles in {}\n", k, triangles.size(), file.string());
      ++written;
    }
    if (written == 0)
      fmt::print(stderr, "{}: no wall is generated as a mesh (truck_drum); nothing written\n",
                 case_file);
    return kExitSuccess;
  } catch (const InputError& error) {
    fmt::print(stderr, "error: {}\n", error.what());
    return kExitBadInput;
  } catch (const RunError& error) {
    fmt::print(stderr, "error: {}\n", error.what());
    return kExitRunFailed;
  } catch (const std::filesystem::filesystem_error& error) {
    fmt::print(stderr, "error: {}\n", error.what());
    return kExitRunFailed;
  }
}

}  // namespace partimix::app
