// Writing a checkpoint; reading one is in checkpoint_reader.cpp.
#include "io/checkpoint_file.hpp"

#include <set>
#include <string>
#include <system_error>

#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/checkpoint_header.hpp"
#include "io/hdf5_handle.hpp"

namespace partimix::io {
namespace {

// Writes an archive into a new HDF5 file at `tmp`; every failure throws RunError naming the
// checkpoint `file` it is for.
class Writer {
 public:
  Writer(const std::filesystem::path& tmp, const std::filesystem::path& file);
  void write(const StateArchive& archive);
  void close();

 private:
  [[noreturn]] void fail(const std::string& what) const;
  Hdf5Handle make(hid_t id, Hdf5Handle::Closer closer, const std::string& what) const;
  void check(herr_t status, const std::string& what) const;
  Hdf5Handle string_type(std::size_t bytes) const;
  void write_text_attribute(const char* name, const std::string& value);
  void write_integer_attribute(const char* name, std::int64_t value);
  void create_groups_along(const std::string& path);
  void write_array(const std::string& path, hid_t file_type, hid_t memory_type, const void* data,
                   std::size_t rows, std::size_t columns);
  void write_text(const std::string& path, const std::string& text);

  std::filesystem::path file_;
  Hdf5Handle hdf5_file_;
  // Without modification times in the object headers (the root group's included, set with the
  // file options), the same archive gives the same bytes.
  Hdf5Handle group_options_;
  Hdf5Handle dataset_options_;
  std::set<std::string> groups_;
};

Writer::Writer(const std::filesystem::path& tmp, const std::filesystem::path& file) : file_(file) {
  Hdf5Handle file_options = make(H5Pcreate(H5P_FILE_CREATE), H5Pclose, "file options");
  check(H5Pset_userblock(file_options.get(), checkpoint_header::kBytes), "the header space");
  check(H5Pset_obj_track_times(file_options.get(), false), "file options");
  Hdf5Handle access = make(H5Pcreate(H5P_FILE_ACCESS), H5Pclose, "file access options");
  check(H5Pset_libver_bounds(access.get(), H5F_LIBVER_V18, H5F_LIBVER_V18), "format bounds");
  hdf5_file_ = make(H5Fcreate(tmp.c_str(), H5F_ACC_TRUNC, file_options.get(), access.get()),
                    H5Fclose, "cannot create '" + tmp.string() + "'");
  group_options_ = make(H5Pcreate(H5P_GROUP_CREATE), H5Pclose, "group options");
  check(H5Pset_obj_track_times(group_options_.get(), false), "group options");
  dataset_options_ = make(H5Pcreate(H5P_DATASET_CREATE), H5Pclose, "dataset options");
  check(H5Pset_obj_track_times(dataset_options_.get(), false), "dataset options");
}

void Writer::fail(const std::string& what) const {
  const std::string detail = hdf5_error_detail();
  throw RunError("cannot write checkpoint '" + file_.string() + "': " + what +
                 (detail.empty() ? "" : " (" + detail + ")"));
}

Hdf5Handle Writer::make(hid_t id, Hdf5Handle::Closer closer, const std::string& what) const {
  if (id < 0) {
    fail(what);
  }
  return {id, closer};
}

void Writer::check(herr_t status, const std::string& what) const {
  if (status < 0) {
    fail(what);
  }
}

// A fixed-length, NUL-terminated UTF-8 string of `bytes` bytes, the terminator included.
Hdf5Handle Writer::string_type(std::size_t bytes) const {
  Hdf5Handle type = make(H5Tcopy(H5T_C_S1), H5Tclose, "string type");
  check(H5Tset_size(type.get(), bytes), "string type");
  check(H5Tset_strpad(type.get(), H5T_STR_NULLTERM), "string type");
  check(H5Tset_cset(type.get(), H5T_CSET_UTF8), "string type");
  return type;
}

void Writer::write_text_attribute(const char* name, const std::string& value) {
  const std::string what = std::string("attribute '") + name + "'";
  const Hdf5Handle type = string_type(value.size() + 1);
  const Hdf5Handle space = make(H5Screate(H5S_SCALAR), H5Sclose, what);
  const Hdf5Handle attribute =
      make(H5Acreate2(hdf5_file_.get(), name, type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT),
           H5Aclose, what);
  check(H5Awrite(attribute.get(), type.get(), value.c_str()), what);
}

void Writer::write_integer_attribute(const char* name, std::int64_t value) {
  const std::string what = std::string("attribute '") + name + "'";
  const Hdf5Handle space = make(H5Screate(H5S_SCALAR), H5Sclose, what);
  const Hdf5Handle attribute =
      make(H5Acreate2(hdf5_file_.get(), name, H5T_STD_I64LE, space.get(), H5P_DEFAULT, H5P_DEFAULT),
           H5Aclose, what);
  check(H5Awrite(attribute.get(), H5T_NATIVE_INT64, &value), what);
}

void Writer::create_groups_along(const std::string& path) {
  for (std::size_t slash = path.find('/'); slash != std::string::npos;
       slash = path.find('/', slash + 1)) {
    const std::string group = path.substr(0, slash);
    if (groups_.insert(group).second) {
      make(H5Gcreate2(hdf5_file_.get(), group.c_str(), H5P_DEFAULT, group_options_.get(),
                      H5P_DEFAULT),
           H5Gclose, "group '" + group + "'");
    }
  }
}

void Writer::write_array(const std::string& path, hid_t file_type, hid_t memory_type,
                         const void* data, std::size_t rows, std::size_t columns) {
  const std::string what = "dataset '" + path + "'";
  const hsize_t dims[2] = {rows, columns};
  const Hdf5Handle space = make(H5Screate_simple(2, dims, nullptr), H5Sclose, what);
  const Hdf5Handle dataset = make(H5Dcreate2(hdf5_file_.get(), path.c_str(), file_type, space.get(),
                                             H5P_DEFAULT, dataset_options_.get(), H5P_DEFAULT),
                                  H5Dclose, what);
  if (rows * columns > 0) {
    check(H5Dwrite(dataset.get(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), what);
  }
}

// The terminator lets an empty text be stored (HDF5 has no zero-length fixed strings) and
// keeps NUL bytes inside a text: the reader takes all bytes but the last.
void Writer::write_text(const std::string& path, const std::string& text) {
  const std::string what = "dataset '" + path + "'";
  const Hdf5Handle type = string_type(text.size() + 1);
  const Hdf5Handle space = make(H5Screate(H5S_SCALAR), H5Sclose, what);
  const Hdf5Handle dataset =
      make(H5Dcreate2(hdf5_file_.get(), path.c_str(), type.get(), space.get(), H5P_DEFAULT,
                      dataset_options_.get(), H5P_DEFAULT),
           H5Dclose, what);
  check(H5Dwrite(dataset.get(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, text.c_str()), what);
}

void Writer::write(const StateArchive& archive) {
  write_text_attribute("format", checkpoint_header::kFormatName);
  write_integer_attribute("format_version", kCheckpointFormatVersion);
  write_text_attribute("partimix_version", PARTIMIX_VERSION);
  for (const auto& [path, entry] : archive.entries()) {
    create_groups_along(path);
    switch (entry.kind) {
      case StateArchive::Kind::doubles:
        write_array(path, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, entry.doubles.data(), entry.rows(),
                    entry.columns);
        break;
      case StateArchive::Kind::integers:
        write_array(path, H5T_STD_I64LE, H5T_NATIVE_INT64, entry.integers.data(), entry.rows(),
                    entry.columns);
        break;
      case StateArchive::Kind::text:
        write_text(path, entry.text);
        break;
    }
  }
}

void Writer::close() {
  check(H5Fflush(hdf5_file_.get(), H5F_SCOPE_LOCAL), "flushing");
  if (!hdf5_file_.close()) {
    fail("closing");
  }
}

}  // namespace

void write_checkpoint(const std::filesystem::path& file, const StateArchive& archive) {
  silence_hdf5_errors();
  replace_atomically(file, [&](const std::filesystem::path& tmp) {
    Writer writer(tmp, file);
    writer.write(archive);
    writer.close();
    checkpoint_header::stamp(tmp, kCheckpointFormatVersion, file);
  });
}

}  // namespace partimix::io
