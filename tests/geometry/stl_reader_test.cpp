// STL reading: ASCII and binary files of a unit cube and a tetrahedron read back to the triangles
// written, binary told from ASCII by its size even behind a "solid" header, coordinates scaled,
// and every bad file (missing, truncated, malformed line, no triangle) an InputError that names
// the file and, for ASCII, the line.
#include <gtest/gtest.h>

#include <cctype>
#include <fstream>
#include <limits>
#include <string>

#include "core/error.hpp"
#include "geometry/lattice.hpp"
#include "geometry/stl_reader.hpp"
#include "geometry/triangle_mesh.hpp"
#include "support/box_mesh.hpp"
#include "support/stl_files.hpp"
#include "support/temp_dir.hpp"

namespace partimix::geometry {
namespace {

using test_support::ascii_stl;
using test_support::binary_stl;
using test_support::box_triangles;

using test_support::TempDir;

TriangleSoup tetrahedron() {
  const Vec3 o(0.0, 0.0, 0.0), x(1.0, 0.0, 0.0), y(0.0, 1.0, 0.0), z(0.0, 0.0, 1.0);
  return {{{o, y, x}}, {{o, x, z}}, {{o, z, y}}, {{x, y, z}}};
}

std::string write(const TempDir& dir, const std::string& name, const std::string& bytes) {
  const std::string path = (dir / name).string();
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

void expect_same_triangles(const TriangleSoup& read, const TriangleSoup& written) {
  ASSERT_EQ(read.size(), written.size());
  for (std::size_t t = 0; t < read.size(); ++t) {
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(read[t].corner[k], written[t].corner[k]) << "triangle " << t << " corner " << k;
    }
  }
}

// The InputError that reading `path` throws; fails the test if it throws none.
InputError read_error(const std::string& path) {
  try {
    read_stl(path);
  } catch (const InputError& error) {
    return error;
  }
  ADD_FAILURE() << "no InputError for " << path;
  return InputError({}, "");
}

TEST(StlReader, ReadsAnAsciiCube) {
  const TempDir dir;
  const TriangleSoup cube = box_triangles(Vec3::Zero(), Vec3::Ones());
  const TriangleSoup read = read_stl(write(dir, "cube.stl", ascii_stl(cube, "cube")));
  expect_same_triangles(read, cube);
  const TriangleMesh mesh(read);
  EXPECT_EQ(mesh.triangle_count(), 12u);
  EXPECT_EQ(mesh.lower(), Vec3::Zero());
  EXPECT_EQ(mesh.upper(), Vec3::Ones());
}

TEST(StlReader, ReadsABinaryCubeAndTetrahedron) {
  const TempDir dir;
  const TriangleSoup cube = box_triangles(Vec3::Zero(), Vec3::Ones());
  expect_same_triangles(read_stl(write(dir, "cube.stl", binary_stl(cube, "cube"))), cube);
  const TriangleSoup tetra = tetrahedron();
  expect_same_triangles(read_stl(write(dir, "tetra.stl", binary_stl(tetra, ""))), tetra);
}

TEST(StlReader, BinaryFileWhoseHeaderStartsWithSolidIsReadAsBinary) {
  const TempDir dir;
  const TriangleSoup cube = box_triangles(Vec3::Zero(), Vec3::Ones());
  const std::string path = write(dir, "cube.stl", binary_stl(cube, "solid cube exported by CAD"));
  expect_same_triangles(read_stl(path), cube);
}

TEST(StlReader, AsciiKeywordsInAnyCaseCrLfAndSeveralSolids) {
  const TempDir dir;
  std::string text = ascii_stl(box_triangles(Vec3::Zero(), Vec3::Ones()), "cube") +
                     ascii_stl(tetrahedron(), "tetra");
  std::string upper_crlf;
  for (char c : text) {
    upper_crlf +=
        c == '\n' ? std::string("\r\n") : std::string(1, static_cast<char>(std::toupper(c)));
  }
  const TriangleSoup read = read_stl(write(dir, "two.stl", upper_crlf));
  ASSERT_EQ(read.size(), 16u);
  EXPECT_EQ(read[15].corner[2], Vec3(0.0, 0.0, 1.0));
}

TEST(StlReader, ScaleMultipliesEveryCoordinate) {
  const TempDir dir;
  const TriangleSoup millimetres =
      box_triangles(Vec3(-500.0, 0.0, 0.0), Vec3(500.0, 250.0, 1000.0));
  const TriangleSoup read = read_stl(write(dir, "mm.stl", ascii_stl(millimetres, "mm")), 1e-3);
  const TriangleMesh mesh(read);
  EXPECT_NEAR((mesh.lower() - Vec3(-0.5, 0.0, 0.0)).norm(), 0.0, 1e-15);
  EXPECT_NEAR((mesh.upper() - Vec3(0.5, 0.25, 1.0)).norm(), 0.0, 1e-15);
}

TEST(StlReader, AsciiCubeInMillimetresFillsLikeTheBox) {
  const TempDir dir;
  const TriangleSoup millimetres = box_triangles(Vec3(10.0, -20.0, 0.0), Vec3(110.0, 30.0, 70.0));
  const std::string path = write(dir, "mm.stl", ascii_stl(millimetres, "mm"));
  const TriangleMesh mesh = read_triangle_mesh(path, 1e-3);
  const Box box(mesh.lower(), mesh.upper());
  const Domain domain;
  const auto from_mesh = fill(mesh, 0.01, domain);
  EXPECT_EQ(from_mesh.size(), 10u * 5u * 7u);
  EXPECT_EQ(from_mesh, fill(box, 0.01, domain));
}

TEST(StlReader, OpenMeshInAFileIsAnInputErrorNamingTheFile) {
  const TempDir dir;
  TriangleSoup open = box_triangles(Vec3::Zero(), Vec3::Ones());
  open.pop_back();
  const std::string path = write(dir, "open.stl", binary_stl(open, "open"));
  try {
    read_triangle_mesh(path);
    ADD_FAILURE() << "no InputError for an open mesh";
  } catch (const InputError& error) {
    EXPECT_EQ(error.location().file, path);
    EXPECT_NE(error.message().find("not closed"), std::string::npos) << error.what();
  }
}

TEST(StlReader, MissingFileIsAnInputErrorNamingIt) {
  const TempDir dir;
  const std::string path = (dir / "nowhere.stl").string();
  const InputError error = read_error(path);
  EXPECT_EQ(error.location().file, path);
  EXPECT_NE(error.message().find("cannot read"), std::string::npos);
}

TEST(StlReader, TruncatedBinaryIsAnInputError) {
  const TempDir dir;
  std::string bytes = binary_stl(box_triangles(Vec3::Zero(), Vec3::Ones()), "solid cube");
  bytes.resize(bytes.size() - 20);
  const std::string path = write(dir, "cut.stl", bytes);
  const InputError error = read_error(path);
  EXPECT_EQ(error.location().file, path);
  EXPECT_NE(error.message().find("truncated"), std::string::npos) << error.what();
  EXPECT_NE(error.message().find("12 triangles"), std::string::npos) << error.what();
}

TEST(StlReader, MalformedAsciiLinesAreReportedWithTheirLineNumber) {
  const TempDir dir;
  const std::string good = ascii_stl(tetrahedron(), "tetra");
  struct Case {
    std::string from, to;
    int line;
    std::string says;
  };
  const Case cases[] = {
      {"vertex 0 0 1\n", "vertex 0 0\n", 13, "expected 'vertex x y z'"},
      {"      vertex 0 1 0\n", "      vertex 0 one 0\n", 5, "'one' is not a finite number"},
      {"endloop\n  endfacet\n  facet", "endloop\n  facet", 8, "expected 'endfacet'"},
      {"solid tetra", "sold tetra", 1, "expected 'solid name'"},
      {"endsolid tetra\n", "", 29, "unexpected end of file"},
  };
  for (const Case& c : cases) {
    std::string bad = good;
    bad.replace(bad.find(c.from), c.from.size(), c.to);
    const std::string path = write(dir, "bad.stl", bad);
    const InputError error = read_error(path);
    EXPECT_EQ(error.location().file, path);
    EXPECT_EQ(error.location().line, c.line) << error.what();
    EXPECT_NE(error.message().find(c.says), std::string::npos) << error.what();
  }
}

TEST(StlReader, NoTriangleAndNonFiniteCoordinatesAreInputErrors) {
  const TempDir dir;
  EXPECT_THROW(read_stl(write(dir, "empty.stl", binary_stl({}, ""))), InputError);
  EXPECT_THROW(read_stl(write(dir, "empty_ascii.stl", "solid empty\nendsolid empty\n")),
               InputError);
  EXPECT_THROW(read_stl(write(dir, "nothing.stl", "")), InputError);
  EXPECT_THROW(read_stl(write(dir, "text.stl", "not an STL file at all\n")), InputError);
  TriangleSoup nan = tetrahedron();
  nan[2].corner[1].y() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(read_stl(write(dir, "nan.stl", binary_stl(nan, ""))), InputError);
  EXPECT_THROW(read_stl(write(dir, "cube.stl", binary_stl(tetrahedron(), "")), 0.0), InputError);
}

}  // namespace
}  // namespace partimix::geometry
