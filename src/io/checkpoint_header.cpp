#include "io/checkpoint_header.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <fstream>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "core/error.hpp"

namespace partimix::io::checkpoint_header {
namespace {

constexpr std::string_view kHdf5Signature("\x89HDF\r\n\x1a\n", 8);
constexpr std::size_t kChunkBytes = std::size_t{1} << 16;

// FNV-1a with 64 bits: needs no library, and a change of any single byte always changes it
// (each step is a bijection of the running hash), which is the damage a checkpoint meets.
class Fnv1a64 {
 public:
  void add(const char* data, std::size_t size) {
    for (std::size_t i = 0; i < size; ++i) {
      hash_ = (hash_ ^ static_cast<unsigned char>(data[i])) * 0x100000001b3ULL;
    }
  }
  std::uint64_t value() const { return hash_; }

 private:
  std::uint64_t hash_ = 0xcbf29ce484222325ULL;
};

// The checksum of everything after the header, or nothing when the file cannot be read.
std::optional<std::uint64_t> checksum_after_header(std::istream& in) {
  in.seekg(static_cast<std::streamoff>(kBytes));
  Fnv1a64 hash;
  std::vector<char> buffer(kChunkBytes);
  while (in) {
    in.read(buffer.data(), static_cast<std::streamsize>(buffer.size()));
    hash.add(buffer.data(), static_cast<std::size_t>(in.gcount()));
  }
  if (in.bad()) {
    return std::nullopt;
  }
  return hash.value();
}

std::string format_header(std::int64_t format_version, std::uintmax_t file_bytes,
                          std::uint64_t checksum) {
  return fmt::format("{}\nformat_version {}\npartimix_version {}\nfile_bytes {}\nfnv1a64 {:016x}\n",
                     kFormatName, format_version, PARTIMIX_VERSION, file_bytes, checksum);
}

std::string first_line() {
  return std::string(kFormatName) + "\n";
}

using HeaderFields = std::map<std::string, std::string, std::less<>>;

// The "key value" lines after the format name, or nothing when the block is not a header: the
// text must end with a newline and the rest of the block must be zeros, so that damage
// anywhere in the block is seen.
std::optional<HeaderFields> parse_fields(std::string_view block) {
  const std::size_t end = block.find('\0');
  if (end == std::string_view::npos ||
      block.find_first_not_of('\0', end) != std::string_view::npos) {
    return std::nullopt;
  }
  const std::string_view text = block.substr(0, end);
  if (!text.starts_with(first_line()) || !text.ends_with('\n')) {
    return std::nullopt;
  }
  HeaderFields fields;
  for (std::size_t begin = first_line().size(); begin < text.size();) {
    const std::size_t line_end = text.find('\n', begin);
    const std::string_view line = text.substr(begin, line_end - begin);
    const std::size_t space = line.find(' ');
    if (space == 0 || space == std::string_view::npos ||
        !fields.emplace(line.substr(0, space), line.substr(space + 1)).second) {
      return std::nullopt;
    }
    begin = line_end + 1;
  }
  return fields;
}

// The field's value as a number in `base`, or nothing when it is missing or not all digits.
template <typename Number>
std::optional<Number> number_field(const HeaderFields& fields, std::string_view key, int base) {
  const auto it = fields.find(key);
  if (it == fields.end() || it->second.empty()) {
    return std::nullopt;
  }
  const std::string& digits = it->second;
  Number value{};
  const auto [rest, error] =
      std::from_chars(digits.data(), digits.data() + digits.size(), value, base);
  if (error != std::errc() || rest != digits.data() + digits.size()) {
    return std::nullopt;
  }
  return value;
}

[[noreturn]] void refuse(const std::filesystem::path& file, const std::string& message) {
  throw InputError(InputLocation{file.string(), 0, 0, ""}, message);
}

std::string read_block(std::istream& in, std::uintmax_t file_size) {
  std::string block(static_cast<std::size_t>(std::min<std::uintmax_t>(file_size, kBytes)), '\0');
  in.read(block.data(), static_cast<std::streamsize>(block.size()));
  block.resize(static_cast<std::size_t>(in.gcount()));
  return block;
}

// Refuses what is plainly not a partimix checkpoint, before looking at the header's fields.
void check_kind(const std::filesystem::path& file, std::string_view block,
                std::uintmax_t file_size) {
  if (file_size == 0) {
    refuse(file, "empty file, not a partimix checkpoint");
  }
  if (block.starts_with(kHdf5Signature)) {
    refuse(file, "an HDF5 file but not a partimix checkpoint (it has no partimix header)");
  }
  const std::string first = first_line();
  if (!block.starts_with(first) && !std::string_view(first).starts_with(block)) {
    refuse(file, "not a partimix checkpoint (it does not start with a partimix header)");
  }
  if (file_size < kBytes) {
    refuse(file, fmt::format("truncated partimix checkpoint: {} bytes, shorter than its header",
                             file_size));
  }
}

}  // namespace

void stamp(const std::filesystem::path& file, std::int64_t format_version,
           const std::filesystem::path& reported_as) {
  const std::string context = "checkpoint '" + reported_as.string() + "'";
  std::error_code error;
  const std::uintmax_t size = std::filesystem::file_size(file, error);
  std::fstream io(file, std::ios::in | std::ios::out | std::ios::binary);
  if (error || !io || size < kBytes) {
    throw RunError("cannot reopen '" + file.string() + "' to finish " + context);
  }
  const std::optional<std::uint64_t> checksum = checksum_after_header(io);
  if (!checksum) {
    throw RunError("cannot read back '" + file.string() + "' to finish " + context);
  }
  const std::string header = format_header(format_version, size, *checksum);
  if (header.size() >= kBytes) {
    throw RunError("the header of " + context + " does not fit in its " + std::to_string(kBytes) +
                   " bytes");
  }
  io.clear();
  io.seekp(0);
  io.write(header.data(), static_cast<std::streamsize>(header.size()));
  io.close();
  if (!io) {
    throw RunError("failed writing the header of " + context);
  }
}

std::uintmax_t verify(const std::filesystem::path& file, std::int64_t format_version) {
  std::error_code error;
  const std::filesystem::file_status status = std::filesystem::status(file, error);
  if (!std::filesystem::exists(status)) {
    refuse(file, "no such checkpoint file");
  }
  if (!std::filesystem::is_regular_file(status)) {
    refuse(file, "not a regular file, so not a partimix checkpoint");
  }
  const std::uintmax_t size = std::filesystem::file_size(file, error);
  std::ifstream in(file, std::ios::binary);
  if (error || !in) {
    refuse(file, "cannot open the checkpoint for reading");
  }
  const std::string block = read_block(in, size);
  check_kind(file, block, size);

  const std::optional<HeaderFields> fields = parse_fields(block);
  const auto version =
      fields ? number_field<std::int64_t>(*fields, "format_version", 10) : std::nullopt;
  if (!version) {
    refuse(file, "damaged partimix checkpoint: its header cannot be read");
  }
  if (*version != format_version) {
    refuse(file, fmt::format("partimix checkpoint of format_version {}; this partimix reads "
                             "format_version {}",
                             *version, format_version));
  }
  const auto expected_size = number_field<std::uintmax_t>(*fields, "file_bytes", 10);
  const auto expected_checksum = number_field<std::uint64_t>(*fields, "fnv1a64", 16);
  if (!expected_size || !expected_checksum) {
    refuse(file, "damaged partimix checkpoint: its header cannot be read");
  }
  if (size != *expected_size) {
    refuse(file,
           fmt::format("{} partimix checkpoint: {} bytes, written with {}",
                       size < *expected_size ? "truncated" : "damaged", size, *expected_size));
  }
  const std::optional<std::uint64_t> checksum = checksum_after_header(in);
  if (!checksum) {
    refuse(file, "cannot read the checkpoint");
  }
  if (*checksum != *expected_checksum) {
    refuse(file,
           "damaged partimix checkpoint: its content does not match the checksum in its "
           "header");
  }
  return size;
}

}  // namespace partimix::io::checkpoint_header
