// Checkpoint files: every kind of entry back bit for bit, the HDF5 layout other tools see, the
// write through a temporary file, and every kind of bad file (missing, foreign, truncated,
// bit-flipped, of another version, or made by hand to pass the header) refused with
// InputError rather than a crash.
#include "io/checkpoint_file.hpp"

#include <gtest/gtest.h>
#include <hdf5.h>

#include <bit>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <functional>
#include <limits>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "core/error.hpp"
#include "io/checkpoint_header.hpp"
#include "io/hdf5_handle.hpp"
#include "io/test_files.hpp"

namespace partimix::io {
namespace {

using test::count_tmp_files;
using test::read_file;
using test::TempDir;

void write_bytes(const std::filesystem::path& file, const std::string& bytes) {
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

// Every kind of entry with the values that round trips through text or conversions lose.
StateArchive sample_archive() {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const std::vector<double> specials = {
      std::numeric_limits<double>::quiet_NaN(),
      std::bit_cast<double>(std::uint64_t{0xfff4000000000123}),  // negative NaN with a payload
      kInf,
      -kInf,
      -0.0,
      0.0,
      std::numeric_limits<double>::denorm_min(),
      -std::numeric_limits<double>::denorm_min() * 12345,
      std::numeric_limits<double>::max(),
      std::numeric_limits<double>::lowest(),
      std::numeric_limits<double>::epsilon(),
      0.1,
  };
  StateArchive archive;
  archive.put_doubles("methods/sph/fields/specials", specials, 2);
  archive.put_integers("methods/sph/fields/id",
                       std::vector<std::int64_t>{std::numeric_limits<std::int64_t>::min(),
                                                 std::numeric_limits<std::int64_t>::max(), 0, -1});
  archive.put_vectors("methods/sph/fields/position",
                      std::vector<Vec3>{{1, 2, 3}, {-0.5, 1e-300, 7}});
  archive.put_scalar("time", 0.123456789012345678);
  archive.put_doubles("empty/doubles", std::vector<double>{}, 3);
  archive.put_integers("empty/integers", std::vector<std::int64_t>{});
  archive.put_text("empty/text", "");
  archive.put_text("case", "fluid:\n  name: \"Größe ∂ρ/∂t 🌀\"\r\n\ttab\n");
  archive.put_text("binary", std::string("a\0b\0", 4));
  std::string deep = "d0";
  for (int level = 1; level < 40; ++level) {
    deep += "/d" + std::to_string(level);
  }
  archive.put_integers(deep, std::vector<std::int64_t>{42});
  for (int i = 0; i < 300; ++i) {
    archive.put_scalar("many/s" + std::to_string(i), i * 0.5);
  }
  return archive;
}

// Same paths, kinds and shapes, doubles equal bit for bit (NaN payloads and -0.0 included).
void expect_identical(const StateArchive& expected, const StateArchive& actual) {
  ASSERT_EQ(expected.paths(), actual.paths());
  for (const auto& [path, want] : expected.entries()) {
    const StateArchive::Entry& got = actual.entries().at(path);
    EXPECT_EQ(got.kind, want.kind) << path;
    EXPECT_EQ(got.columns, want.columns) << path;
    EXPECT_EQ(got.integers, want.integers) << path;
    EXPECT_EQ(got.text, want.text) << path;
    ASSERT_EQ(got.doubles.size(), want.doubles.size()) << path;
    for (std::size_t i = 0; i < want.doubles.size(); ++i) {
      EXPECT_EQ(std::bit_cast<std::uint64_t>(got.doubles[i]),
                std::bit_cast<std::uint64_t>(want.doubles[i]))
          << path << "[" << i << "]";
    }
  }
}

// The message of the InputError that reading file throws, "" when it reads.
std::string read_error(const std::filesystem::path& file) {
  try {
    read_checkpoint(file);
  } catch (const InputError& error) {
    EXPECT_EQ(error.location().file, file.string());
    return error.message();
  }
  return "";
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// An HDF5 file laid out as a checkpoint (user block, root attributes of `version`), with what
// `fill` adds, then given a header that passes: what a buggy or hostile writer could make.
void write_crafted(const std::filesystem::path& file, const std::function<void(hid_t)>& fill,
                   std::int64_t version = kCheckpointFormatVersion, bool attributes = true) {
  {
    const Hdf5Handle options(H5Pcreate(H5P_FILE_CREATE), H5Pclose);
    H5Pset_userblock(options.get(), checkpoint_header::kBytes);
    const Hdf5Handle h5(H5Fcreate(file.c_str(), H5F_ACC_TRUNC, options.get(), H5P_DEFAULT),
                        H5Fclose);
    ASSERT_TRUE(h5.valid());
    if (attributes) {
      const Hdf5Handle scalar(H5Screate(H5S_SCALAR), H5Sclose);
      const Hdf5Handle text(H5Tcopy(H5T_C_S1), H5Tclose);
      H5Tset_size(text.get(), std::strlen(checkpoint_header::kFormatName) + 1);
      const Hdf5Handle format(
          H5Acreate2(h5.get(), "format", text.get(), scalar.get(), H5P_DEFAULT, H5P_DEFAULT),
          H5Aclose);
      H5Awrite(format.get(), text.get(), checkpoint_header::kFormatName);
      const Hdf5Handle number(H5Acreate2(h5.get(), "format_version", H5T_STD_I64LE, scalar.get(),
                                         H5P_DEFAULT, H5P_DEFAULT),
                              H5Aclose);
      H5Awrite(number.get(), H5T_NATIVE_INT64, &version);
    }
    fill(h5.get());
  }
  checkpoint_header::stamp(file, version, file);
}

// A dataset of `type` and shape `dims` (rank = dims.size()), written with zeros unless it is
// too large to write.
void add_dataset(hid_t file, const char* name, hid_t type, const std::vector<hsize_t>& dims,
                 hid_t options = H5P_DEFAULT) {
  const Hdf5Handle space(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr),
                         H5Sclose);
  const Hdf5Handle dataset(
      H5Dcreate2(file, name, type, space.get(), H5P_DEFAULT, options, H5P_DEFAULT), H5Dclose);
  ASSERT_TRUE(dataset.valid()) << name;
  hsize_t count = 1;
  for (const hsize_t n : dims) {
    count *= n;
  }
  if (count <= 1024) {
    const std::vector<double> zeros(count + 1, 0.0);  // 8 bytes per value covers every type here
    H5Dwrite(dataset.get(), type, H5S_ALL, H5S_ALL, H5P_DEFAULT, zeros.data());
  }
}

TEST(CheckpointFile, RoundTripsEveryKindBitForBit) {
  const TempDir dir;
  const StateArchive archive = sample_archive();
  write_checkpoint(dir / "state.h5", archive);
  expect_identical(archive, read_checkpoint(dir / "state.h5"));
}

TEST(CheckpointFile, RoundTripsAnEmptyArchive) {
  const TempDir dir;
  write_checkpoint(dir / "empty.h5", StateArchive());
  EXPECT_TRUE(read_checkpoint(dir / "empty.h5").paths().empty());
}

// What h5dump, h5py or another program sees: attributes at the root, entries as 2-D datasets
// of little-endian doubles and integers, and texts as fixed-length strings.
TEST(CheckpointFile, IsAPlainHdf5FileWithTheDocumentedLayout) {
  const TempDir dir;
  StateArchive archive;
  archive.put_vectors("methods/sph/position", std::vector<Vec3>(5, Vec3(1, 2, 3)));
  archive.put_integers("methods/sph/id", std::vector<std::int64_t>(5, 7));
  archive.put_text("case", "yaml");
  write_checkpoint(dir / "c.h5", archive);

  const std::string bytes = read_file(dir / "c.h5");
  EXPECT_TRUE(bytes.starts_with("partimix-checkpoint\nformat_version 1\n"));
  EXPECT_EQ(bytes.substr(checkpoint_header::kBytes, 4), "\x89HDF");
  const Hdf5Handle h5(H5Fopen((dir / "c.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  ASSERT_TRUE(h5.valid());
  for (const char* name : {"format", "format_version", "partimix_version"}) {
    EXPECT_GT(H5Aexists(h5.get(), name), 0) << name;
  }
  const Hdf5Handle version(H5Aopen(h5.get(), "format_version", H5P_DEFAULT), H5Aclose);
  std::int64_t number = 0;
  H5Aread(version.get(), H5T_NATIVE_INT64, &number);
  EXPECT_EQ(number, 1);

  const Hdf5Handle position(H5Dopen2(h5.get(), "methods/sph/position", H5P_DEFAULT), H5Dclose);
  const Hdf5Handle type(H5Dget_type(position.get()), H5Tclose);
  EXPECT_GT(H5Tequal(type.get(), H5T_IEEE_F64LE), 0);
  const Hdf5Handle space(H5Dget_space(position.get()), H5Sclose);
  hsize_t dims[2] = {0, 0};
  ASSERT_EQ(H5Sget_simple_extent_ndims(space.get()), 2);
  H5Sget_simple_extent_dims(space.get(), dims, nullptr);
  EXPECT_EQ(dims[0], 5u);
  EXPECT_EQ(dims[1], 3u);
  const Hdf5Handle id(H5Dopen2(h5.get(), "methods/sph/id", H5P_DEFAULT), H5Dclose);
  const Hdf5Handle id_type(H5Dget_type(id.get()), H5Tclose);
  EXPECT_GT(H5Tequal(id_type.get(), H5T_STD_I64LE), 0);
  const Hdf5Handle text(H5Dopen2(h5.get(), "case", H5P_DEFAULT), H5Dclose);
  const Hdf5Handle text_type(H5Dget_type(text.get()), H5Tclose);
  EXPECT_EQ(H5Tget_class(text_type.get()), H5T_STRING);
}

TEST(CheckpointFile, SameArchiveGivesSameBytes) {
  const TempDir dir;
  const StateArchive archive = sample_archive();
  write_checkpoint(dir / "a.h5", archive);
  // HDF5 stamps object headers in whole seconds: the two files are written in different ones.
  std::this_thread::sleep_for(std::chrono::milliseconds(1100));
  write_checkpoint(dir / "b.h5", archive);
  EXPECT_EQ(read_file(dir / "a.h5"), read_file(dir / "b.h5"));
}

TEST(CheckpointFile, ReplacesAnOldFileAndLeavesNoTemporary) {
  const TempDir dir;
  StateArchive first;
  first.put_scalar("time", 1.0);
  write_checkpoint(dir / "c.h5", first);
  StateArchive second;
  second.put_scalar("time", 2.0);
  write_checkpoint(dir / "c.h5", second);
  EXPECT_EQ(read_checkpoint(dir / "c.h5").scalar("time"), 2.0);
  EXPECT_EQ(count_tmp_files(dir.path()), 0);
}

TEST(CheckpointFile, UnwritableFolderGivesRunErrorNamingTheFile) {
  const TempDir dir;
  write_bytes(dir / "plain_file", "x");
  // Root may write anywhere, so the folders are ones that cannot hold a file at all.
  for (const auto& file : {dir / "missing/c.h5", dir / "plain_file/c.h5"}) {
    try {
      write_checkpoint(file, sample_archive());
      ADD_FAILURE() << "no error writing " << file;
    } catch (const RunError& error) {
      EXPECT_TRUE(contains(error.what(), file.string())) << error.what();
    }
  }
  EXPECT_EQ(count_tmp_files(dir.path()), 0);
}

TEST(CheckpointFile, MissingFileIsInputError) {
  const TempDir dir;
  EXPECT_TRUE(contains(read_error(dir / "none.h5"), "no such")) << read_error(dir / "none.h5");
  EXPECT_TRUE(contains(read_error(dir.path()), "not a regular file"));
}

TEST(CheckpointFile, EmptyAndTextFilesAreInputErrors) {
  const TempDir dir;
  write_bytes(dir / "empty.h5", "");
  EXPECT_TRUE(contains(read_error(dir / "empty.h5"), "empty")) << read_error(dir / "empty.h5");
  write_bytes(dir / "text.h5", "time: 1.0\nsteps: 5\n");
  EXPECT_TRUE(contains(read_error(dir / "text.h5"), "not a partimix checkpoint"));
  write_bytes(dir / "long_text.h5", std::string(5000, 'x'));
  EXPECT_TRUE(contains(read_error(dir / "long_text.h5"), "not a partimix checkpoint"));
}

TEST(CheckpointFile, Hdf5FileFromAnotherProgramIsInputError) {
  const TempDir dir;
  {
    const Hdf5Handle h5(
        H5Fcreate((dir / "other.h5").c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose);
    add_dataset(h5.get(), "temperature", H5T_IEEE_F64LE, {4, 1});
  }
  const std::string message = read_error(dir / "other.h5");
  EXPECT_TRUE(contains(message, "HDF5 file but not a partimix checkpoint")) << message;
}

TEST(CheckpointFile, TruncatedCheckpointIsInputError) {
  const TempDir dir;
  write_checkpoint(dir / "full.h5", sample_archive());
  const std::string bytes = read_file(dir / "full.h5");
  for (const std::size_t length :
       {std::size_t{1}, std::size_t{20}, std::size_t{511}, std::size_t{512}, std::size_t{513},
        std::size_t{2048}, bytes.size() / 2, bytes.size() - 8, bytes.size() - 1}) {
    write_bytes(dir / "cut.h5", bytes.substr(0, length));
    const std::string message = read_error(dir / "cut.h5");
    EXPECT_TRUE(contains(message, "truncated")) << length << ": " << message;
  }
}

TEST(CheckpointFile, ExtraBytesAtTheEndAreInputError) {
  const TempDir dir;
  write_checkpoint(dir / "c.h5", sample_archive());
  write_bytes(dir / "c.h5", read_file(dir / "c.h5") + "more");
  EXPECT_TRUE(contains(read_error(dir / "c.h5"), "damaged"));
}

// Damage anywhere (header, HDF5 metadata, raw data) either changes nothing that is read or is
// refused: never a crash, a hang or values that differ.
TEST(CheckpointFile, FlippedBytesReadIdenticallyOrGiveInputError) {
  const TempDir dir;
  const StateArchive archive = sample_archive();
  write_checkpoint(dir / "good.h5", archive);
  const std::string bytes = read_file(dir / "good.h5");
  std::mt19937_64 random(20240611);
  int refused = 0;
  constexpr int kTrials = 240;
  for (int trial = 0; trial < kTrials; ++trial) {
    std::string damaged = bytes;
    // A third of the trials hit the header, the rest anywhere; one to four bytes each.
    const std::size_t span = trial % 3 == 0 ? checkpoint_header::kBytes : bytes.size();
    for (std::uint64_t flips = 1 + random() % 4; flips > 0; --flips) {
      damaged[random() % span] ^= static_cast<char>(1 + random() % 255);
    }
    write_bytes(dir / "bad.h5", damaged);
    try {
      expect_identical(archive, read_checkpoint(dir / "bad.h5"));
    } catch (const InputError&) {
      ++refused;
    }
  }
  EXPECT_GT(refused, kTrials * 9 / 10);
}

TEST(CheckpointFile, OtherFormatVersionIsInputError) {
  const TempDir dir;
  write_checkpoint(dir / "c.h5", sample_archive());
  std::string bytes = read_file(dir / "c.h5");
  bytes.replace(bytes.find("format_version 1\n"), 17, "format_version 2\n");
  write_bytes(dir / "c.h5", bytes);
  const std::string message = read_error(dir / "c.h5");
  EXPECT_TRUE(contains(message, "format_version 2")) << message;
  EXPECT_TRUE(contains(message, "reads format_version 1")) << message;

  // The same with a header that passes: the root attribute is checked too.
  write_crafted(
      dir / "v2.h5", [](hid_t) {}, 2);
  EXPECT_TRUE(contains(read_error(dir / "v2.h5"), "format_version 2"));
}

TEST(CheckpointFile, HandMadeFileWithoutRootAttributesIsInputError) {
  const TempDir dir;
  write_crafted(
      dir / "c.h5",
      [](hid_t h5) {
        add_dataset(h5, "x", H5T_IEEE_F64LE, {1, 1});
      },
      kCheckpointFormatVersion, false);
  EXPECT_TRUE(contains(read_error(dir / "c.h5"), "no root attribute 'format'"));
}

TEST(CheckpointFile, HandMadeFileIsReadWhenItFollowsTheLayout) {
  const TempDir dir;
  write_crafted(dir / "c.h5", [](hid_t h5) { add_dataset(h5, "x", H5T_IEEE_F64LE, {2, 3}); });
  EXPECT_EQ(read_checkpoint(dir / "c.h5").doubles("x", 3).size(), 6u);
}

TEST(CheckpointFile, DatasetOfUnexpectedTypeIsInputError) {
  const TempDir dir;
  for (const hid_t type : {H5T_IEEE_F32LE, H5T_IEEE_F64BE, H5T_STD_I32LE, H5T_STD_U64LE}) {
    write_crafted(dir / "c.h5", [&](hid_t h5) { add_dataset(h5, "x", type, {2, 1}); });
    const std::string message = read_error(dir / "c.h5");
    EXPECT_TRUE(contains(message, "dataset 'x' holds neither")) << message;
  }
}

TEST(CheckpointFile, DatasetOfUnexpectedRankIsInputError) {
  const TempDir dir;
  for (const std::vector<hsize_t>& dims :
       {std::vector<hsize_t>{4}, std::vector<hsize_t>{2, 2, 2}, std::vector<hsize_t>{3, 0}}) {
    write_crafted(dir / "c.h5", [&](hid_t h5) { add_dataset(h5, "x", H5T_STD_I64LE, dims); });
    const std::string message = read_error(dir / "c.h5");
    EXPECT_TRUE(contains(message, "not a 2-D array")) << message;
  }
}

TEST(CheckpointFile, DatasetLargerThanTheFileIsInputError) {
  const TempDir dir;
  write_crafted(dir / "c.h5", [](hid_t h5) {
    add_dataset(h5, "huge", H5T_IEEE_F64LE, {hsize_t{1} << 40, 1});
    add_dataset(h5, "overflow", H5T_IEEE_F64LE, {hsize_t{1} << 62, hsize_t{1} << 62});
  });
  const std::string message = read_error(dir / "c.h5");
  EXPECT_TRUE(contains(message, "claims more data than the file holds")) << message;
}

TEST(CheckpointFile, ChunkedDatasetAndVariableLengthTextAreInputErrors) {
  const TempDir dir;
  write_crafted(dir / "chunked.h5", [](hid_t h5) {
    const Hdf5Handle options(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
    const hsize_t chunk[2] = {1, 1};
    H5Pset_chunk(options.get(), 2, chunk);
    add_dataset(h5, "x", H5T_IEEE_F64LE, {2, 1}, options.get());
  });
  EXPECT_TRUE(contains(read_error(dir / "chunked.h5"), "storage layout"));

  write_crafted(dir / "vlen.h5", [](hid_t h5) {
    const Hdf5Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
    H5Tset_size(type.get(), H5T_VARIABLE);
    const Hdf5Handle space(H5Screate(H5S_SCALAR), H5Sclose);
    const Hdf5Handle text(
        H5Dcreate2(h5, "t", type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
        H5Dclose);
    const char* value = "hello";
    H5Dwrite(text.get(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, &value);
  });
  EXPECT_TRUE(contains(read_error(dir / "vlen.h5"), "not a single fixed-length string"));
}

TEST(CheckpointFile, LinksAndNamesPartimixDoesNotWriteAreInputErrors) {
  const TempDir dir;
  write_crafted(dir / "soft.h5", [](hid_t h5) {
    add_dataset(h5, "x", H5T_IEEE_F64LE, {1, 1});
    H5Lcreate_soft("/x", h5, "alias", H5P_DEFAULT, H5P_DEFAULT);
  });
  EXPECT_TRUE(contains(read_error(dir / "soft.h5"), "soft or external link"));

  write_crafted(dir / "hard.h5", [](hid_t h5) {
    const Hdf5Handle group(H5Gcreate2(h5, "g", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
    H5Lcreate_hard(h5, "/", group.get(), "loop", H5P_DEFAULT, H5P_DEFAULT);
  });
  EXPECT_TRUE(contains(read_error(dir / "hard.h5"), "second link"));

  write_crafted(dir / "name.h5", [](hid_t h5) {
    add_dataset(h5, "with space", H5T_IEEE_F64LE, {1, 1});
  });
  EXPECT_TRUE(contains(read_error(dir / "name.h5"), "is not a state path"));
}

}  // namespace
}  // namespace partimix::io
