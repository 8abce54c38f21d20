// A grid frame (.vti) read back strictly: an ImageData of the grid's cells (extent in points,
// origin and spacing), the time, and each cell array decoded from the raw binary.
#include "io/vti_frame_writer.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

#include "io/test_files.hpp"
#include "support/vtk_xml.hpp"

namespace partimix::io {
namespace {

using test::decode;
using test::find_tag;
using test::parse_frame;
using test::ParsedFrame;
using test::read_file;
using test::TempDir;

GridFrame three_by_two(const std::vector<double>& velocity, const std::vector<double>& pressure) {
  GridFrame frame;
  frame.dimensions = 3;
  frame.origin = Vec3(-1.0, 0.5, 2.0);
  frame.spacing = Vec3(0.25, 0.5, 0.125);
  frame.cells = {3, 2, 1};
  frame.cell_arrays = {{"velocity", 3, velocity}, {"pressure", 1, pressure}};
  return frame;
}

TEST(VtiFrameWriter, DescribesTheCellsAndKeepsEveryValue) {
  TempDir dir;
  std::vector<double> velocity(18), pressure(6);
  for (std::size_t k = 0; k < velocity.size(); ++k)
    velocity[k] = 0.1 * static_cast<double>(k) - 1.0 / 3.0;
  for (std::size_t c = 0; c < pressure.size(); ++c)
    pressure[c] = 101325.0 + static_cast<double>(c) / 7.0;
  write_vti_frame(dir / "frame.vti", three_by_two(velocity, pressure), 0.75);
  const ParsedFrame frame = parse_frame(read_file(dir / "frame.vti"));
  EXPECT_EQ(find_tag(frame, "VTKFile").attributes.at("type"), "ImageData");
  const auto& image = find_tag(frame, "ImageData").attributes;
  EXPECT_EQ(image.at("WholeExtent"), "0 3 0 2 0 1");
  EXPECT_EQ(image.at("Origin"), "-1 0.5 2");
  EXPECT_EQ(image.at("Spacing"), "0.25 0.5 0.125");
  EXPECT_EQ(find_tag(frame, "Piece").attributes.at("Extent"), "0 3 0 2 0 1");
  test::expect_offsets_tile_block(frame, 6);
  EXPECT_EQ(decode<double>(frame, "TimeValue"), std::vector<double>{0.75});
  EXPECT_EQ(decode<double>(frame, "velocity"), velocity);
  EXPECT_EQ(decode<double>(frame, "pressure"), pressure);
  ASSERT_EQ(frame.arrays.size(), 3U);
  EXPECT_EQ(frame.arrays[1].section, "CellData");
  EXPECT_EQ(frame.arrays[1].attributes.at("NumberOfComponents"), "3");
}

// In 2D the image is flat: no extent across the plane, the grid's unit depth not shown.
TEST(VtiFrameWriter, TwoDimensionalGridIsFlat) {
  TempDir dir;
  const std::vector<double> velocity(18, 0.0), pressure(6, 1.0);
  GridFrame grid = three_by_two(velocity, pressure);
  grid.dimensions = 2;
  write_vti_frame(dir / "frame.vti", grid, 0.0);
  const ParsedFrame frame = parse_frame(read_file(dir / "frame.vti"));
  const auto& image = find_tag(frame, "ImageData").attributes;
  EXPECT_EQ(image.at("WholeExtent"), "0 3 0 2 0 0");
  EXPECT_EQ(image.at("Origin"), "-1 0.5 0");
  test::expect_offsets_tile_block(frame, 6);
}

TEST(VtiFrameWriter, RejectsAnArrayOfTheWrongSizeAndWritesNothing) {
  TempDir dir;
  const std::vector<double> velocity(17, 0.0), pressure(6, 1.0);
  EXPECT_THROW(write_vti_frame(dir / "frame.vti", three_by_two(velocity, pressure), 0.0),
               std::invalid_argument);
  EXPECT_FALSE(std::filesystem::exists(dir / "frame.vti"));
  EXPECT_EQ(test::count_tmp_files(dir.path()), 0);
}

}  // namespace
}  // namespace partimix::io
