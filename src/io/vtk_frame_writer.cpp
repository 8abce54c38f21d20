#include "io/vtk_frame_writer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <functional>
#include <iterator>
#include <numeric>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "io/atomic_file.hpp"
#include "io/vtk_appended.hpp"

namespace partimix::io {
namespace {

static_assert(std::endian::native == std::endian::little, "frames are written as LittleEndian");
static_assert(sizeof(Vec3) == 3 * sizeof(double), "Vec3 must be three packed doubles");

// The arrays of a frame in file order; the XML header and the appended block follow it.
struct Frame {
  std::size_t points = 0;
  std::vector<AppendedArray> field_data;
  std::vector<AppendedArray> point_data;
  std::vector<AppendedArray> coordinates;
  std::vector<AppendedArray> verts;
};

// Writes first, first + 1, ..., first + count - 1 as Int64 through a fixed-size buffer.
void write_counting(std::ostream& out, std::size_t count, std::int64_t first) {
  constexpr std::size_t kChunk = 4096;
  std::array<std::int64_t, kChunk> buffer{};
  for (std::size_t begin = 0; begin < count; begin += kChunk) {
    const std::size_t n = std::min(kChunk, count - begin);
    std::iota(buffer.begin(), buffer.begin() + n, first + static_cast<std::int64_t>(begin));
    out.write(reinterpret_cast<const char*>(buffer.data()),
              static_cast<std::streamsize>(n * sizeof(std::int64_t)));
  }
}

AppendedArray counting_array(const std::string& name, std::size_t count, std::int64_t first) {
  return {name, "Int64", 1, count, count * sizeof(std::int64_t), [count, first](std::ostream& out) {
            write_counting(out, count, first);
          }};
}

template <class T>
void add_output_fields(std::vector<AppendedArray>& arrays, const std::deque<Field<T>>& fields,
                       std::string_view type, int components) {
  for (const auto& field : fields) {
    if (field.output) {
      arrays.push_back(raw_array(field.name, type, components, std::span<const T>(field.values)));
    }
  }
}

Frame describe_frame(const ParticleStore& store, const double& time,
                     std::span<const FrameArray> extra) {
  Frame frame;
  frame.points = store.size();
  frame.field_data.push_back(
      raw_array("TimeValue", "Float64", 1, std::span<const double>(&time, 1)));
  add_output_fields(frame.point_data, store.scalar_fields(), "Float64", 1);
  add_output_fields(frame.point_data, store.vector_fields(), "Float64", 3);
  add_output_fields(frame.point_data, store.integer_fields(), "Int32", 1);
  add_output_fields(frame.point_data, store.id_fields(), "Int64", 1);
  add_frame_arrays(frame.point_data, extra, frame.points);
  frame.coordinates.push_back(
      raw_array("Points", "Float64", 3, std::span<const Vec3>(store.position())));
  frame.verts.push_back(counting_array("connectivity", frame.points, 0));
  frame.verts.push_back(counting_array("offsets", frame.points, 1));
  return frame;
}

std::string xml_header(const Frame& frame) {
  std::string xml =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\" "
      "header_type=\"UInt64\">\n"
      "  <PolyData>\n";
  std::uint64_t offset = 0;
  describe_section(xml, "FieldData", "    ", frame.field_data, true, offset);
  fmt::format_to(std::back_inserter(xml),
                 "    <Piece NumberOfPoints=\"{0}\" NumberOfVerts=\"{0}\" NumberOfLines=\"0\" "
                 "NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n",
                 frame.points);
  describe_section(xml, "PointData", "      ", frame.point_data, false, offset);
  describe_section(xml, "Points", "      ", frame.coordinates, false, offset);
  describe_section(xml, "Verts", "      ", frame.verts, false, offset);
  xml +=
      "    </Piece>\n"
      "  </PolyData>\n"
      "  <AppendedData encoding=\"raw\">\n"
      "   _";
  return xml;
}

void write_frame(std::ostream& out, const Frame& frame) {
  out << xml_header(frame);
  write_block(out, frame.field_data);
  write_block(out, frame.point_data);
  write_block(out, frame.coordinates);
  write_block(out, frame.verts);
  out << "\n  </AppendedData>\n</VTKFile>\n";
}

}  // namespace

void write_vtp_frame(const std::filesystem::path& file, const ParticleStore& store, double time,
                     std::span<const FrameArray> extra) {
  const Frame frame = describe_frame(store, time, extra);
  write_atomically(file, [&frame](std::ostream& out) { write_frame(out, frame); });
}

}  // namespace partimix::io
