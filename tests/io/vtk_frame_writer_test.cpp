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
#include "support/vtk_xml.hpp"

namespace partimix::io {
namespace {

using test::decode;
using test::expect_offsets_tile_block;
using test::find_array;
using test::find_tag;
using test::parse_frame;
using test::ParsedFrame;
using test::read_file;
using test::TempDir;

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
