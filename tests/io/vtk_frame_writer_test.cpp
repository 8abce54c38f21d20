// A .vtp frame read back strictly (our stand-in for ParaView): XML header, array list, offsets
// that tile the appended block exactly, and every value decoded from the raw binary.
#include "io/vtk_frame_writer.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <map>
#include <regex>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "io/test_files.hpp"

namespace partimix::io {
namespace {

using test::read_file;
using test::TempDir;

struct Tag {
  std::string name;
  std::map<std::string, std::string> attributes;
};

struct ArrayInfo {
  std::string section;  // FieldData, PointData, Points or Verts
  std::map<std::string, std::string> attributes;
};

// The frame split at the '_' that starts the appended block.
struct ParsedFrame {
  std::vector<Tag> tags;  // opening tags in file order
  std::vector<ArrayInfo> arrays;
  std::string block;  // appended block, without the closing tags
};

std::map<std::string, std::string> parse_attributes(const std::string& text) {
  static const std::regex attribute(R"re(([A-Za-z_]+)="([^"]*)")re");
  std::map<std::string, std::string> attributes;
  for (std::sregex_iterator it(text.begin(), text.end(), attribute), end; it != end; ++it) {
    attributes[(*it)[1]] = (*it)[2];
  }
  return attributes;
}

void parse_header(const std::string& header, ParsedFrame& frame) {
  static const std::regex tag(R"re(<(/?)([A-Za-z]+)([^>]*)>)re");
  std::string section;
  for (std::sregex_iterator it(header.begin(), header.end(), tag), end; it != end; ++it) {
    const std::string name = (*it)[2];
    if ((*it)[1] == "/")
      continue;
    Tag parsed{name, parse_attributes((*it)[3])};
    if (name == "FieldData" || name == "PointData" || name == "Points" || name == "Verts") {
      section = name;
    }
    if (name == "DataArray")
      frame.arrays.push_back({section, parsed.attributes});
    frame.tags.push_back(parsed);
  }
}

ParsedFrame parse_frame(const std::string& text) {
  const std::string marker = "<AppendedData encoding=\"raw\">";
  const std::string trailer = "\n  </AppendedData>\n</VTKFile>\n";
  const auto at = text.find(marker);
  EXPECT_NE(at, std::string::npos);
  const auto underscore = text.find('_', at + marker.size());
  EXPECT_EQ(text.substr(at + marker.size(), underscore - at - marker.size()), "\n   ");
  EXPECT_EQ(text.substr(text.size() - trailer.size()), trailer);
  ParsedFrame frame;
  parse_header(text.substr(0, underscore), frame);
  frame.block = text.substr(underscore + 1, text.size() - trailer.size() - underscore - 1);
  return frame;
}

const Tag& find_tag(const ParsedFrame& frame, const std::string& name) {
  for (const auto& tag : frame.tags) {
    if (tag.name == name)
      return tag;
  }
  ADD_FAILURE() << "no <" << name << "> tag";
  static const Tag none;
  return none;
}

const ArrayInfo& find_array(const ParsedFrame& frame, const std::string& name) {
  for (const auto& array : frame.arrays) {
    if (array.attributes.at("Name") == name)
      return array;
  }
  ADD_FAILURE() << "no DataArray " << name;
  static const ArrayInfo none;
  return none;
}

template <class T>
std::vector<T> decode(const ParsedFrame& frame, const std::string& name) {
  const std::uint64_t offset = std::stoull(find_array(frame, name).attributes.at("offset"));
  std::uint64_t bytes = 0;
  std::memcpy(&bytes, frame.block.data() + offset, sizeof(bytes));
  EXPECT_EQ(bytes % sizeof(T), 0U) << name;
  EXPECT_LE(offset + sizeof(bytes) + bytes, frame.block.size()) << name;
  std::vector<T> values(bytes / sizeof(T));
  std::memcpy(values.data(), frame.block.data() + offset + sizeof(bytes), bytes);
  return values;
}

std::size_t type_size(const std::string& type) {
  if (type == "Float64" || type == "Int64")
    return 8;
  if (type == "Int32")
    return 4;
  ADD_FAILURE() << "unexpected type " << type;
  return 1;
}

// Each array's byte count must match its type, components and tuples, and the arrays must
// follow one another in the appended block with no gap and nothing after the last.
void expect_offsets_tile_block(const ParsedFrame& frame, std::size_t points) {
  std::uint64_t expected_offset = 0;
  for (const auto& array : frame.arrays) {
    const auto& a = array.attributes;
    const std::string& name = a.at("Name");
    ASSERT_EQ(std::stoull(a.at("offset")), expected_offset) << name;
    ASSERT_LE(expected_offset + 8, frame.block.size()) << name;
    std::uint64_t bytes = 0;
    std::memcpy(&bytes, frame.block.data() + expected_offset, sizeof(bytes));
    const std::size_t tuples = array.section == "FieldData" ? 1 : points;
    EXPECT_EQ(bytes, tuples * std::stoull(a.at("NumberOfComponents")) * type_size(a.at("type")))
        << name;
    EXPECT_EQ(a.at("format"), "appended") << name;
    expected_offset += 8 + bytes;
  }
  EXPECT_EQ(expected_offset, frame.block.size());
}

void fill_store(ParticleStore& store) {
  auto& pressure = store.add_scalar("pressure", "Pa");
  auto& acceleration = store.add_vector("acceleration", "m/s^2", false);
  store.resize(3);
  for (std::size_t i = 0; i < 3; ++i) {
    const double x = static_cast<double>(i);
    store.id()[i] = 100 + static_cast<std::int64_t>(i);
    store.kind()[i] = static_cast<std::int32_t>(i % 2);
    store.tag()[i] = static_cast<std::int32_t>(7 * i);
    store.position()[i] = Vec3(x + 0.125, -x, 1e-300 * x);
    store.velocity()[i] = Vec3(0.1 * x, 1.0 / 3.0, -2.5e10);
    store.mass()[i] = 1.0;
    pressure.values[i] = 101325.0 + x / 7.0;
    acceleration.values[i] = Vec3(9.0, 9.0, 9.0);
  }
}

TEST(VtkFrameWriter, HeaderDescribesPolyDataWithTime) {
  TempDir dir;
  ParticleStore store;
  fill_store(store);
  write_vtp_frame(dir / "frame.vtp", store, 0.375);
  const ParsedFrame frame = parse_frame(read_file(dir / "frame.vtp"));
  const auto& file = find_tag(frame, "VTKFile").attributes;
  EXPECT_EQ(file.at("type"), "PolyData");
  EXPECT_EQ(file.at("version"), "1.0");
  EXPECT_EQ(file.at("byte_order"), "LittleEndian");
  EXPECT_EQ(file.at("header_type"), "UInt64");
  const auto& piece = find_tag(frame, "Piece").attributes;
  EXPECT_EQ(piece.at("NumberOfPoints"), "3");
  EXPECT_EQ(piece.at("NumberOfVerts"), "3");
  EXPECT_EQ(piece.at("NumberOfLines"), "0");
  EXPECT_EQ(piece.at("NumberOfPolys"), "0");
  EXPECT_EQ(piece.at("NumberOfStrips"), "0");
  EXPECT_EQ(find_array(frame, "TimeValue").attributes.at("NumberOfTuples"), "1");
  EXPECT_EQ(decode<double>(frame, "TimeValue"), std::vector<double>{0.375});
}

TEST(VtkFrameWriter, ListsExactlyTheOutputFields) {
  TempDir dir;
  ParticleStore store;
  fill_store(store);
  write_vtp_frame(dir / "frame.vtp", store, 0.0);
  const ParsedFrame frame = parse_frame(read_file(dir / "frame.vtp"));
  const std::vector<std::vector<std::string>> expected = {
      {"FieldData", "TimeValue", "Float64", "1"}, {"PointData", "pressure", "Float64", "1"},
      {"PointData", "velocity", "Float64", "3"},  {"PointData", "kind", "Int32", "1"},
      {"PointData", "tag", "Int32", "1"},         {"PointData", "id", "Int64", "1"},
      {"Points", "Points", "Float64", "3"},       {"Verts", "connectivity", "Int64", "1"},
      {"Verts", "offsets", "Int64", "1"}};
  ASSERT_EQ(frame.arrays.size(), expected.size());
  for (std::size_t k = 0; k < expected.size(); ++k) {
    const auto& a = frame.arrays[k].attributes;
    EXPECT_EQ(frame.arrays[k].section, expected[k][0]) << k;
    EXPECT_EQ(a.at("Name"), expected[k][1]) << k;
    EXPECT_EQ(a.at("type"), expected[k][2]) << k;
    EXPECT_EQ(a.at("NumberOfComponents"), expected[k][3]) << k;
  }
  expect_offsets_tile_block(frame, 3);
}

TEST(VtkFrameWriter, BinaryValuesRoundTripExactly) {
  TempDir dir;
  ParticleStore store;
  fill_store(store);
  write_vtp_frame(dir / "frame.vtp", store, 1.0);
  const ParsedFrame frame = parse_frame(read_file(dir / "frame.vtp"));
  const auto points = decode<double>(frame, "Points");
  const auto velocity = decode<double>(frame, "velocity");
  ASSERT_EQ(points.size(), 9U);
  ASSERT_EQ(velocity.size(), 9U);
  for (std::size_t i = 0; i < 3; ++i) {
    for (std::size_t c = 0; c < 3; ++c) {
      EXPECT_EQ(points[3 * i + c], store.position()[i][static_cast<Eigen::Index>(c)]);
      EXPECT_EQ(velocity[3 * i + c], store.velocity()[i][static_cast<Eigen::Index>(c)]);
    }
  }
  EXPECT_EQ(decode<double>(frame, "pressure"), store.find_scalar("pressure")->values);
  EXPECT_EQ(decode<std::int64_t>(frame, "id"), store.id());
  EXPECT_EQ(decode<std::int32_t>(frame, "kind"), store.kind());
  EXPECT_EQ(decode<std::int32_t>(frame, "tag"), store.tag());
  EXPECT_EQ(decode<std::int64_t>(frame, "connectivity"), (std::vector<std::int64_t>{0, 1, 2}));
  EXPECT_EQ(decode<std::int64_t>(frame, "offsets"), (std::vector<std::int64_t>{1, 2, 3}));
}

TEST(VtkFrameWriter, FrameArraysFollowTheFieldsWithTheirComponents) {
  TempDir dir;
  ParticleStore store;
  fill_store(store);
  std::vector<double> tensor(27);
  std::vector<double> pair{2.0, 2.0, 4.0, 6.0, 2.0, 10.0};
  for (std::size_t k = 0; k < tensor.size(); ++k)
    tensor[k] = 0.5 * static_cast<double>(k);
  const std::vector<FrameArray> extra{{"shape_tensor", 9, tensor}, {"blockiness", 2, pair}};
  write_vtp_frame(dir / "frame.vtp", store, 0.0, extra);
  const ParsedFrame frame = parse_frame(read_file(dir / "frame.vtp"));
  std::vector<std::string> point_data;
  for (const auto& array : frame.arrays) {
    if (array.section == "PointData")
      point_data.push_back(array.attributes.at("Name"));
  }
  EXPECT_EQ(point_data, (std::vector<std::string>{"pressure", "velocity", "kind", "tag", "id",
                                                  "shape_tensor", "blockiness"}));
  EXPECT_EQ(find_array(frame, "shape_tensor").attributes.at("NumberOfComponents"), "9");
  EXPECT_EQ(find_array(frame, "blockiness").attributes.at("NumberOfComponents"), "2");
  EXPECT_EQ(decode<double>(frame, "shape_tensor"), tensor);
  EXPECT_EQ(decode<double>(frame, "blockiness"), pair);
  expect_offsets_tile_block(frame, 3);
}

TEST(VtkFrameWriter, NoFrameArraysWriteTheFieldsAlone) {
  TempDir dir;
  ParticleStore store;
  fill_store(store);
  write_vtp_frame(dir / "plain.vtp", store, 0.25);
  write_vtp_frame(dir / "none.vtp", store, 0.25, std::vector<FrameArray>{});
  EXPECT_EQ(read_file(dir / "plain.vtp"), read_file(dir / "none.vtp"));
}

TEST(VtkFrameWriter, AFrameArrayOfTheWrongSizeIsRefused) {
  TempDir dir;
  ParticleStore store;
  fill_store(store);
  const std::vector<double> short_of_one(8);
  const std::vector<FrameArray> extra{{"orientation", 3, short_of_one}};
  EXPECT_THROW(write_vtp_frame(dir / "frame.vtp", store, 0.0, extra), std::invalid_argument);
}

TEST(VtkFrameWriter, LongConnectivitySpansSeveralBufferChunks) {
  TempDir dir;
  ParticleStore store;
  store.resize(10000);
  write_vtp_frame(dir / "frame.vtp", store, 0.0);
  const ParsedFrame frame = parse_frame(read_file(dir / "frame.vtp"));
  expect_offsets_tile_block(frame, 10000);
  const auto connectivity = decode<std::int64_t>(frame, "connectivity");
  const auto offsets = decode<std::int64_t>(frame, "offsets");
  ASSERT_EQ(connectivity.size(), 10000U);
  ASSERT_EQ(offsets.size(), 10000U);
  for (std::size_t i = 0; i < connectivity.size(); ++i) {
    ASSERT_EQ(connectivity[i], static_cast<std::int64_t>(i));
    ASSERT_EQ(offsets[i], static_cast<std::int64_t>(i + 1));
  }
}

TEST(VtkFrameWriter, EmptyStoreGivesValidEmptyFrame) {
  TempDir dir;
  ParticleStore store;
  write_vtp_frame(dir / "frame.vtp", store, 0.0);
  const ParsedFrame frame = parse_frame(read_file(dir / "frame.vtp"));
  EXPECT_EQ(find_tag(frame, "Piece").attributes.at("NumberOfPoints"), "0");
  expect_offsets_tile_block(frame, 0);
}

TEST(VtkFrameWriter, RewriteLeavesNoTemporaryFile) {
  TempDir dir;
  ParticleStore store;
  fill_store(store);
  write_vtp_frame(dir / "frame.vtp", store, 0.0);
  store.resize(1);
  write_vtp_frame(dir / "frame.vtp", store, 1.0);
  const ParsedFrame frame = parse_frame(read_file(dir / "frame.vtp"));
  EXPECT_EQ(find_tag(frame, "Piece").attributes.at("NumberOfPoints"), "1");
  EXPECT_EQ(test::count_tmp_files(dir.path()), 0);
}

TEST(VtkFrameWriter, UnwritableFolderThrowsRunErrorNamingFile) {
  TempDir dir;
  ParticleStore store;
  const auto file = dir / "missing" / "frame.vtp";
  try {
    write_vtp_frame(file, store, 0.0);
    FAIL() << "expected RunError";
  } catch (const RunError& error) {
    EXPECT_NE(std::string(error.what()).find(file.string()), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace partimix::io
