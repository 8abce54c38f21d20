// libFuzzer target: the STL reader, geometry::read_stl (src/geometry/stl_reader.hpp), and what
// a mesh wall of a case goes through after it (src/io/walls_section.cpp).
//
// Input: the bytes of an STL file, ASCII or binary, written to a fixed file in a per-process
// folder under /tmp and read with scale 1. The triangles read then become a TriangleMesh (weld,
// closure and orientation checks, pseudo-normals, bounding volume hierarchy); a soup that is no
// closed mesh becomes a MeshShellSurface instead, as an open mesh wall does. A few points
// around the mesh are then queried (signed distance, nearest surface point).
//
// Expected: success, or partimix::InputError from read_stl or from the TriangleMesh checks. A
// finding: any other exception (reported and aborted on), a crash, a sanitizer report (ASan,
// UBSan, LeakSanitizer), a timeout, running out of memory, or a query on a mesh of finite
// corners that answers a non-finite distance or normal.
#include <unistd.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <string>
#include <typeinfo>

#include "core/error.hpp"
#include "geometry/mesh_shell_surface.hpp"
#include "geometry/stl_reader.hpp"
#include "geometry/triangle_mesh.hpp"

namespace {

using partimix::Vec3;
namespace geometry = partimix::geometry;

const std::filesystem::path& stl_file() {
  static const std::filesystem::path file =
      std::filesystem::temp_directory_path() /
      ("partimix-fuzz-stl-" + std::to_string(static_cast<long>(::getpid())) + ".stl");
  return file;
}

void remove_stl_file() {
  std::error_code ignored;
  std::filesystem::remove(stl_file(), ignored);
}

[[noreturn]] void fail(const char* what) {
  std::fprintf(stderr, "stl_reader_fuzz: %s\n", what);
  std::abort();
}

// The bounding box's centre, points beyond two of its corners, and the first triangle's centroid.
std::array<Vec3, 4> probe_points(const geometry::TriangleSoup& soup) {
  Vec3 lower = soup.front().corner[0];
  Vec3 upper = lower;
  for (const geometry::Triangle& t : soup) {
    for (const Vec3& c : t.corner) {
      lower = lower.cwiseMin(c);
      upper = upper.cwiseMax(c);
    }
  }
  const Vec3 size = upper - lower;
  const auto& first = soup.front().corner;
  return {0.5 * (lower + upper), lower - 0.25 * size - Vec3::Ones(),
          upper + 0.25 * size + Vec3::Ones(), (first[0] + first[1] + first[2]) / 3.0};
}

void query(const geometry::Surface& surface, const std::array<Vec3, 4>& points) {
  for (const Vec3& x : points) {
    geometry::SurfacePoint contact;
    if (x.allFinite() && surface.nearest(x, std::numeric_limits<double>::infinity(), contact) &&
        (!contact.point.allFinite() || !contact.normal.allFinite() ||
         !std::isfinite(contact.gap))) {
      fail("MeshShellSurface::nearest answered a non-finite point, normal or gap");
    }
  }
}

void build_and_query(const geometry::TriangleSoup& soup) {
  const std::array<Vec3, 4> points = probe_points(soup);
  std::unique_ptr<geometry::Surface> surface;
  try {
    const geometry::TriangleMesh mesh(soup);
    for (const Vec3& x : points) {
      if (x.allFinite() && !std::isfinite(mesh.signed_distance(x))) {
        fail("TriangleMesh::signed_distance answered a non-finite distance");
      }
    }
    surface = mesh.make_surface(false, {});
  } catch (const partimix::InputError&) {
    surface = std::make_unique<geometry::MeshShellSurface>(soup);  // an open mesh wall
  }
  query(*surface, points);
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int* /*argc*/, char*** /*argv*/) {
  std::atexit(remove_stl_file);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  {
    std::ofstream out(stl_file(), std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    if (!out) {
      fail("cannot write the STL file");
    }
  }
  try {
    const geometry::TriangleSoup soup = geometry::read_stl(stl_file().string(), 1.0);
    build_and_query(soup);
  } catch (const partimix::InputError&) {
    // The expected refusal of a bad file or a mesh that is not closed.
  } catch (const std::exception& error) {
    std::fprintf(stderr, "stl_reader_fuzz: unexpected %s: %s\n", typeid(error).name(),
                 error.what());
    std::abort();
  }
  return 0;
}
