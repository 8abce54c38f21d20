// Reading a checkpoint (io/checkpoint_file.hpp). The header check has already refused every
// file that is not byte for byte what partimix wrote; this still checks every object, type,
// rank and size, so that a file made by hand to pass the header fails with InputError too,
// and it allocates no more than the file's size in all.
#include <fmt/format.h>

#include <cstdint>
#include <set>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "io/checkpoint_file.hpp"
#include "io/checkpoint_header.hpp"
#include "io/hdf5_handle.hpp"

namespace partimix::io {
namespace {

// Names from a file may hold anything: show them short and printable.
std::string printable(const std::string& name) {
  constexpr std::size_t kShown = 100;
  std::string shown;
  for (const char c : name.substr(0, kShown)) {
    shown += (c >= ' ' && c <= '~') ? c : '?';
  }
  return name.size() > kShown ? shown + "..." : shown;
}

struct Link {
  std::string name;
  H5L_type_t type;
};

herr_t collect_link(hid_t /*group*/, const char* name, const H5L_info_t* info, void* links) {
  try {
    static_cast<std::vector<Link>*>(links)->push_back({name, info->type});
    return 0;
  } catch (...) {
    return -1;  // out of memory: HDF5 stops iterating and reports a failure
  }
}

class Reader {
 public:
  Reader(const std::filesystem::path& file, std::uintmax_t file_size);
  StateArchive read();

 private:
  [[noreturn]] void refuse(const std::string& message) const;
  [[noreturn]] void refuse_hdf5(const std::string& what) const;
  [[noreturn]] void refuse_oversized(const std::string& path) const;
  Hdf5Handle make(hid_t id, Hdf5Handle::Closer closer, const std::string& what) const;
  void take(std::uintmax_t bytes, const std::string& path);
  Hdf5Handle scalar_attribute(const char* name, H5T_class_t type_class) const;
  void check_attributes() const;
  std::vector<Link> links_of(hid_t group, const std::string& path) const;
  void visit(hid_t group, const Link& link, const std::string& path, StateArchive& archive,
             std::vector<std::string>& pending);
  void read_dataset(hid_t group, const std::string& name, const std::string& path,
                    StateArchive& archive);
  void read_array(hid_t dataset, hid_t type, hid_t space, const std::string& path,
                  StateArchive& archive);
  void read_text(hid_t dataset, hid_t type, hid_t space, const std::string& path,
                 StateArchive& archive);

  std::filesystem::path file_;
  std::uintmax_t budget_;   // bytes the datasets may still hold: no more than the file does
  std::set<haddr_t> seen_;  // objects met, so that hard-link cycles end
  Hdf5Handle hdf5_file_;
};

Reader::Reader(const std::filesystem::path& file, std::uintmax_t file_size)
    : file_(file), budget_(file_size) {
  hdf5_file_ = make(H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose,
                    "HDF5 cannot open the checkpoint");
}

void Reader::refuse(const std::string& message) const {
  throw InputError(InputLocation{file_.string(), 0, 0, ""}, message);
}

void Reader::refuse_hdf5(const std::string& what) const {
  const std::string detail = hdf5_error_detail();
  refuse("damaged partimix checkpoint: " + what + (detail.empty() ? "" : " (" + detail + ")"));
}

Hdf5Handle Reader::make(hid_t id, Hdf5Handle::Closer closer, const std::string& what) const {
  if (id < 0) {
    refuse_hdf5(what);
  }
  return {id, closer};
}

void Reader::refuse_oversized(const std::string& path) const {
  refuse("damaged partimix checkpoint: dataset '" + path +
         "' claims more data than the file holds");
}

void Reader::take(std::uintmax_t bytes, const std::string& path) {
  if (bytes > budget_) {
    refuse_oversized(path);
  }
  budget_ -= bytes;
}

// An attribute of the root group holding one value of the given class.
Hdf5Handle Reader::scalar_attribute(const char* name, H5T_class_t type_class) const {
  if (H5Aexists(hdf5_file_.get(), name) <= 0) {
    refuse(std::string("not a partimix checkpoint: no root attribute '") + name + "'");
  }
  const std::string what = std::string("root attribute '") + name + "'";
  Hdf5Handle attribute = make(H5Aopen(hdf5_file_.get(), name, H5P_DEFAULT), H5Aclose, what);
  const Hdf5Handle type = make(H5Aget_type(attribute.get()), H5Tclose, what);
  const Hdf5Handle space = make(H5Aget_space(attribute.get()), H5Sclose, what);
  if (H5Tget_class(type.get()) != type_class || H5Tis_variable_str(type.get()) > 0 ||
      H5Sget_simple_extent_type(space.get()) != H5S_SCALAR) {
    refuse("not a partimix checkpoint: " + what + " has an unexpected type");
  }
  return attribute;
}

void Reader::check_attributes() const {
  const Hdf5Handle format = scalar_attribute("format", H5T_STRING);
  const std::string expected = checkpoint_header::kFormatName;
  const Hdf5Handle type = make(H5Aget_type(format.get()), H5Tclose, "root attribute 'format'");
  std::string value(expected.size() + 1, '\0');
  if (H5Tget_size(type.get()) != value.size() ||
      H5Aread(format.get(), type.get(), value.data()) < 0 || value != expected + '\0') {
    refuse("not a partimix checkpoint: root attribute 'format' is not '" + expected + "'");
  }
  const Hdf5Handle version = scalar_attribute("format_version", H5T_INTEGER);
  std::int64_t number = 0;
  if (H5Aread(version.get(), H5T_NATIVE_INT64, &number) < 0) {
    refuse_hdf5("cannot read root attribute 'format_version'");
  }
  if (number != kCheckpointFormatVersion) {
    refuse(
        fmt::format("partimix checkpoint of format_version {}; this partimix reads "
                    "format_version {}",
                    number, kCheckpointFormatVersion));
  }
}

std::vector<Link> Reader::links_of(hid_t group, const std::string& path) const {
  std::vector<Link> links;
  if (H5Literate(group, H5_INDEX_NAME, H5_ITER_INC, nullptr, collect_link, &links) < 0) {
    refuse_hdf5("cannot list group '" + printable(path) + "'");
  }
  return links;
}

void Reader::visit(hid_t group, const Link& link, const std::string& path, StateArchive& archive,
                   std::vector<std::string>& pending) {
  if (link.name.find('/') != std::string::npos || !StateArchive::is_valid_path(link.name)) {
    refuse("not a partimix checkpoint: '" + printable(path) + "' is not a state path");
  }
  if (link.type != H5L_TYPE_HARD) {
    refuse("not a partimix checkpoint: '" + printable(path) + "' is a soft or external link");
  }
  H5O_info_t info;
  if (H5Oget_info_by_name2(group, link.name.c_str(), &info, H5O_INFO_BASIC, H5P_DEFAULT) < 0) {
    refuse_hdf5("cannot open '" + path + "'");
  }
  if (!seen_.insert(info.addr).second) {
    refuse("not a partimix checkpoint: '" + path + "' is a second link to an object");
  }
  if (info.type == H5O_TYPE_GROUP) {
    pending.push_back(path);
  } else if (info.type == H5O_TYPE_DATASET) {
    read_dataset(group, link.name, path, archive);
  } else {
    refuse("not a partimix checkpoint: '" + path + "' is neither a group nor a dataset");
  }
}

void Reader::read_dataset(hid_t group, const std::string& name, const std::string& path,
                          StateArchive& archive) {
  const std::string what = "dataset '" + path + "'";
  const std::string opening = "cannot open " + what;
  const Hdf5Handle dataset = make(H5Dopen2(group, name.c_str(), H5P_DEFAULT), H5Dclose, opening);
  const Hdf5Handle options = make(H5Dget_create_plist(dataset.get()), H5Pclose, opening);
  const H5D_layout_t layout = H5Pget_layout(options.get());
  // Chunks, filters, external raw files and virtual datasets are never written by partimix,
  // and each lets HDF5 allocate or open what the file's size does not bound.
  if ((layout != H5D_CONTIGUOUS && layout != H5D_COMPACT) ||
      H5Pget_external_count(options.get()) != 0) {
    refuse("not a partimix checkpoint: " + what + " has a storage layout partimix does not write");
  }
  const Hdf5Handle type = make(H5Dget_type(dataset.get()), H5Tclose, opening);
  const Hdf5Handle space = make(H5Dget_space(dataset.get()), H5Sclose, opening);
  if (H5Tget_class(type.get()) == H5T_STRING) {
    read_text(dataset.get(), type.get(), space.get(), path, archive);
  } else {
    read_array(dataset.get(), type.get(), space.get(), path, archive);
  }
}

void Reader::read_array(hid_t dataset, hid_t type, hid_t space, const std::string& path,
                        StateArchive& archive) {
  const bool is_double = H5Tequal(type, H5T_IEEE_F64LE) > 0;
  if (!is_double && H5Tequal(type, H5T_STD_I64LE) <= 0) {
    refuse("not a partimix checkpoint: dataset '" + path +
           "' holds neither 64-bit little-endian doubles or integers nor a string");
  }
  hsize_t dims[2] = {0, 0};
  if (H5Sget_simple_extent_type(space) != H5S_SIMPLE || H5Sget_simple_extent_ndims(space) != 2 ||
      H5Sget_simple_extent_dims(space, dims, nullptr) != 2 || dims[1] == 0) {
    refuse("not a partimix checkpoint: dataset '" + path +
           "' is not a 2-D array [rows, columns] with at least one column");
  }
  // Compared by division, so that a product of hostile dimensions cannot overflow.
  if (dims[0] > 0 && dims[1] > budget_ / 8 / dims[0]) {
    refuse_oversized(path);
  }
  const std::size_t count = dims[0] * dims[1];
  take(8 * count, path);
  const hid_t memory_type = is_double ? H5T_NATIVE_DOUBLE : H5T_NATIVE_INT64;
  std::vector<double> doubles(is_double ? count : 0);
  std::vector<std::int64_t> integers(is_double ? 0 : count);
  void* buffer = is_double ? static_cast<void*>(doubles.data()) : integers.data();
  if (count > 0 && H5Dread(dataset, memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, buffer) < 0) {
    refuse_hdf5("cannot read dataset '" + path + "'");
  }
  if (is_double) {
    archive.put_doubles(path, doubles, dims[1]);
  } else {
    archive.put_integers(path, integers, dims[1]);
  }
}

void Reader::read_text(hid_t dataset, hid_t type, hid_t space, const std::string& path,
                       StateArchive& archive) {
  const std::size_t bytes = H5Tget_size(type);
  if (H5Tis_variable_str(type) != 0 || H5Sget_simple_extent_type(space) != H5S_SCALAR ||
      bytes == 0) {
    refuse("not a partimix checkpoint: dataset '" + path + "' is not a single fixed-length string");
  }
  take(bytes, path);
  std::string text(bytes, '\0');
  if (H5Dread(dataset, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, text.data()) < 0) {
    refuse_hdf5("cannot read dataset '" + path + "'");
  }
  if (text.back() != '\0') {
    refuse("damaged partimix checkpoint: the text '" + path + "' is not NUL-terminated");
  }
  text.pop_back();
  archive.put_text(path, std::move(text));
}

StateArchive Reader::read() {
  check_attributes();
  H5O_info_t root;
  if (H5Oget_info2(hdf5_file_.get(), &root, H5O_INFO_BASIC) < 0) {
    refuse_hdf5("cannot open the root group");
  }
  seen_.insert(root.addr);
  StateArchive archive;
  // Depth first with an explicit list, so that a deep file cannot exhaust the stack.
  std::vector<std::string> pending{""};
  while (!pending.empty()) {
    const std::string group_path = std::move(pending.back());
    pending.pop_back();
    const char* name = group_path.empty() ? "/" : group_path.c_str();
    const Hdf5Handle group = make(H5Gopen2(hdf5_file_.get(), name, H5P_DEFAULT), H5Gclose,
                                  "cannot open group '" + group_path + "'");
    for (const Link& link : links_of(group.get(), group_path)) {
      const std::string path = group_path.empty() ? link.name : group_path + "/" + link.name;
      visit(group.get(), link, path, archive, pending);
    }
  }
  return archive;
}

}  // namespace

StateArchive read_checkpoint(const std::filesystem::path& file) {
  silence_hdf5_errors();
  const std::uintmax_t size = checkpoint_header::verify(file, kCheckpointFormatVersion);
  Reader reader(file, size);
  return reader.read();
}

}  // namespace partimix::io
