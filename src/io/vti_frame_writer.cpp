#include "io/vti_frame_writer.hpp"

#include <iterator>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "io/atomic_file.hpp"
#include "io/vtk_appended.hpp"

namespace partimix::io {
namespace {

// The image's extent in points: cells + 1 along each axis, none across a 2D grid's plane.
std::string whole_extent(const GridFrame& frame) {
  const int nz = frame.dimensions == 2 ? 0 : frame.cells[2];
  return fmt::format("0 {} 0 {} 0 {}", frame.cells[0], frame.cells[1], nz);
}

// VTK's Direction: the matrix whose columns are the image's axes in the world, row after row.
std::string direction_attribute(const Mat3& direction) {
  std::string text = " Direction=\"";
  for (int row = 0; row < 3; ++row)
    for (int column = 0; column < 3; ++column)
      fmt::format_to(std::back_inserter(text), "{}{:.17g}", row + column == 0 ? "" : " ",
                     direction(row, column));
  return text + "\"";
}

std::string xml_header(const GridFrame& frame, const std::vector<AppendedArray>& field_data,
                       const std::vector<AppendedArray>& cell_data) {
  const std::string extent = whole_extent(frame);
  const double dz = frame.dimensions == 2 ? 1.0 : frame.spacing[2];
  const double z0 = frame.dimensions == 2 ? 0.0 : frame.origin[2];
  std::string xml =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"ImageData\" version=\"1.0\" byte_order=\"LittleEndian\" "
      "header_type=\"UInt64\">\n";
  const std::string direction =
      frame.direction.isIdentity(0.0) ? "" : direction_attribute(frame.direction);
  fmt::format_to(std::back_inserter(xml),
                 "  <ImageData WholeExtent=\"{}\" Origin=\"{:.17g} {:.17g} {:.17g}\" "
                 "Spacing=\"{:.17g} {:.17g} {:.17g}\"{}>\n",
                 extent, frame.origin[0], frame.origin[1], z0, frame.spacing[0], frame.spacing[1],
                 dz, direction);
  std::uint64_t offset = 0;
  describe_section(xml, "FieldData", "    ", field_data, true, offset);
  fmt::format_to(std::back_inserter(xml), "    <Piece Extent=\"{}\">\n", extent);
  describe_section(xml, "CellData", "      ", cell_data, false, offset);
  xml +=
      "    </Piece>\n"
      "  </ImageData>\n"
      "  <AppendedData encoding=\"raw\">\n"
      "   _";
  return xml;
}

}  // namespace

void write_vti_frame(const std::filesystem::path& file, const GridFrame& frame, double time) {
  const std::vector<AppendedArray> field_data{
      raw_array("TimeValue", "Float64", 1, std::span<const double>(&time, 1))};
  std::vector<AppendedArray> cell_data;
  add_frame_arrays(cell_data, frame.cell_arrays, frame.cell_count());
  write_atomically(file, [&](std::ostream& out) {
    out << xml_header(frame, field_data, cell_data);
    write_block(out, field_data);
    write_block(out, cell_data);
    out << "\n  </AppendedData>\n</VTKFile>\n";
  });
}

}  // namespace partimix::io
