#include "geometry/stl_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <ios>
#include <iterator>
#include <string_view>
#include <system_error>

#include "core/error.hpp"

namespace partimix::geometry {
namespace {

// Binary STL layout: an 80-byte header, a little-endian uint32 triangle count, then per
// triangle a normal and three corners (12 little-endian float32) and a 2-byte attribute.
constexpr std::uint64_t kCountOffset = 80;
constexpr std::uint64_t kFirstTriangleOffset = 84;
constexpr std::uint64_t kBytesPerTriangle = 50;
constexpr std::uint64_t kFirstCornerInTriangle = 12;
constexpr std::uint64_t kBytesPerCorner = 12;

InputError stl_error(const std::string& path, const std::string& message, int line = 0,
                     int column = 0) {
  return InputError(InputLocation{path, line, column, ""}, message);
}

// Only a regular file: a folder opens as a stream and fails at its first read, with an
// exception of the stream buffer whatever the stream's exception mask (a case whose mesh `file`
// is "" names the case's folder), and a device or a pipe may never end (/dev/zero).
std::string read_whole_file(const std::string& path) {
  std::error_code error;
  const std::filesystem::file_status status = std::filesystem::status(path, error);
  if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status)) {
    throw stl_error(path, "cannot read the STL file: not a regular file");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw stl_error(path, "cannot read the STL file: no such readable file");
  }
  std::string bytes;
  try {
    bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  } catch (const std::ios_base::failure&) {
    throw stl_error(path, "cannot read the STL file: read error");
  }
  if (in.bad()) {
    throw stl_error(path, "cannot read the STL file: read error");
  }
  return bytes;
}

std::uint32_t little_endian_u32(const char* bytes) {
  std::uint32_t value = 0;
  std::memcpy(&value, bytes, sizeof value);
  if constexpr (std::endian::native == std::endian::big) {
    value = ((value & 0x000000FFu) << 24) | ((value & 0x0000FF00u) << 8) |
            ((value & 0x00FF0000u) >> 8) | ((value & 0xFF000000u) >> 24);
  }
  return value;
}

float little_endian_float(const char* bytes) {
  return std::bit_cast<float>(little_endian_u32(bytes));
}

bool is_keyword(std::string_view word, std::string_view keyword) {
  return std::ranges::equal(word, keyword, [](char a, char b) {
    return std::tolower(static_cast<unsigned char>(a)) == b;
  });
}

bool is_space(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v';
}

// Binary STL counts and attributes are full of zero bytes; text has none. So a file that is not
// exactly the size its binary header announces is read as ASCII when it holds no zero byte, and
// a text file that is no STL then fails on its first line rather than as a binary of odd size.
bool looks_like_text(const std::string& bytes) {
  return bytes.find('\0') == std::string::npos;
}

std::uint64_t binary_size_for(std::uint64_t count) {
  return kFirstTriangleOffset + kBytesPerTriangle * count;
}

bool is_binary(const std::string& bytes) {
  return bytes.size() >= kFirstTriangleOffset &&
         bytes.size() == binary_size_for(little_endian_u32(bytes.data() + kCountOffset));
}

TriangleSoup parse_binary(const std::string& bytes, const std::string& path, double scale) {
  const std::uint32_t count = little_endian_u32(bytes.data() + kCountOffset);
  TriangleSoup soup(count);
  for (std::uint32_t t = 0; t < count; ++t) {
    const char* corners =
        bytes.data() + kFirstTriangleOffset + kBytesPerTriangle * t + kFirstCornerInTriangle;
    for (std::uint64_t k = 0; k < 3; ++k) {
      const char* xyz = corners + kBytesPerCorner * k;
      Vec3& corner = soup[t].corner[k];
      for (int axis = 0; axis < 3; ++axis) {
        corner[axis] = scale * static_cast<double>(little_endian_float(xyz + 4 * axis));
      }
      if (!corner.allFinite()) {
        throw stl_error(
            path, fmt::format("triangle {}: a corner coordinate is not a finite number", t + 1));
      }
    }
  }
  return soup;
}

struct Word {
  std::string_view text;
  int column = 0;
};

// One non-blank line of an ASCII STL: its 1-based number, its text and its words.
struct Line {
  int number = 0;
  std::string_view text;
  std::vector<Word> words;
};

class LineCursor {
 public:
  explicit LineCursor(std::string_view text) : text_(text) {}

  // Moves to the next non-blank line; false at the end of the text.
  bool next(Line& line) {
    while (position_ < text_.size()) {
      read_line(line);
      if (!line.words.empty()) {
        return true;
      }
    }
    return false;
  }

  int lines_read() const { return number_; }

 private:
  void read_line(Line& line) {
    const std::size_t end = std::min(text_.find('\n', position_), text_.size());
    line.number = ++number_;
    line.text = text_.substr(position_, end - position_);
    line.words.clear();
    split_words(line);
    position_ = end + 1;
  }

  static void split_words(Line& line) {
    const std::string_view text = line.text;
    std::size_t i = 0;
    while (i < text.size()) {
      while (i < text.size() && is_space(text[i])) {
        ++i;
      }
      const std::size_t start = i;
      while (i < text.size() && !is_space(text[i])) {
        ++i;
      }
      if (i > start) {
        line.words.push_back({text.substr(start, i - start), static_cast<int>(start) + 1});
      }
    }
  }

  std::string_view text_;
  std::size_t position_ = 0;
  int number_ = 0;
};

// solid name / { facet normal n n n / outer loop / 3 x vertex x y z / endloop / endfacet } /
// endsolid name, repeated for files that hold several solids. Keywords in any letter case.
class AsciiParser {
 public:
  AsciiParser(std::string_view text, const std::string& path, double scale)
      : lines_(text), path_(path), scale_(scale) {}

  TriangleSoup parse() {
    TriangleSoup soup;
    while (lines_.next(line_)) {
      if (!is_keyword(line_.words[0].text, "solid")) {
        throw unexpected(line_.words[0], "'solid name'");
      }
      parse_solid_body(soup);
    }
    return soup;
  }

 private:
  void parse_solid_body(TriangleSoup& soup) {
    while (true) {
      next_line("'facet normal nx ny nz' or 'endsolid'");
      if (is_keyword(line_.words[0].text, "endsolid")) {
        return;
      }
      expect({"facet", "normal"}, 5, "'facet normal nx ny nz' or 'endsolid'");
      soup.push_back(parse_facet_body());
    }
  }

  Triangle parse_facet_body() {
    expect_line({"outer", "loop"}, 2, "'outer loop'");
    Triangle triangle;
    for (Vec3& corner : triangle.corner) {
      expect_line({"vertex"}, 4, "'vertex x y z'");
      for (int axis = 0; axis < 3; ++axis) {
        corner[axis] = scale_ * parse_number(line_.words[static_cast<std::size_t>(axis) + 1]);
      }
      if (!corner.allFinite()) {
        throw error_at(line_.words[1], "a corner coordinate is not a finite number");
      }
    }
    expect_line({"endloop"}, 1, "'endloop'");
    expect_line({"endfacet"}, 1, "'endfacet'");
    return triangle;
  }

  void next_line(std::string_view expected) {
    if (!lines_.next(line_)) {
      throw stl_error(path_, fmt::format("unexpected end of file, expected {}", expected),
                      lines_.lines_read());
    }
  }

  void expect_line(std::initializer_list<std::string_view> keywords, std::size_t word_count,
                   std::string_view expected) {
    next_line(expected);
    expect(keywords, word_count, expected);
  }

  void expect(std::initializer_list<std::string_view> keywords, std::size_t word_count,
              std::string_view expected) {
    std::size_t i = 0;
    for (std::string_view keyword : keywords) {
      if (i >= line_.words.size() || !is_keyword(line_.words[i].text, keyword)) {
        throw unexpected(line_.words[std::min(i, line_.words.size() - 1)], expected);
      }
      ++i;
    }
    if (line_.words.size() != word_count) {
      throw unexpected(line_.words.front(), expected);
    }
  }

  double parse_number(const Word& word) {
    std::string_view text = word.text;
    if (!text.empty() && text.front() == '+') {
      text.remove_prefix(1);
    }
    double value = 0.0;
    const auto [end, status] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (status != std::errc{} || end != text.data() + text.size()) {
      throw error_at(word, fmt::format("'{}' is not a finite number (in '{}')", word.text,
                                       trimmed(line_.text)));
    }
    return value;
  }

  InputError unexpected(const Word& word, std::string_view expected) const {
    return error_at(word, fmt::format("expected {}, found '{}'", expected, trimmed(line_.text)));
  }

  InputError error_at(const Word& word, const std::string& message) const {
    return stl_error(path_, message, line_.number, word.column);
  }

  static std::string_view trimmed(std::string_view text) {
    const auto first = std::ranges::find_if_not(text, is_space);
    const auto last = std::find_if_not(text.rbegin(), text.rend(), is_space).base();
    return first < last ? std::string_view(first, last) : std::string_view();
  }

  LineCursor lines_;
  Line line_;
  const std::string& path_;
  double scale_;
};

TriangleSoup parse_any(const std::string& bytes, const std::string& path, double scale) {
  if (is_binary(bytes)) {
    return parse_binary(bytes, path, scale);
  }
  if (looks_like_text(bytes)) {
    return AsciiParser(bytes, path, scale).parse();
  }
  if (bytes.size() < kFirstTriangleOffset) {
    throw stl_error(path, fmt::format("not an STL file: {} bytes of binary data, too short for "
                                      "the 84-byte binary header",
                                      bytes.size()));
  }
  const std::uint32_t count = little_endian_u32(bytes.data() + kCountOffset);
  throw stl_error(path, fmt::format("binary STL of the wrong size (truncated?): its header "
                                    "announces {} triangles, {} bytes, but the file has {} bytes",
                                    count, binary_size_for(count), bytes.size()));
}

}  // namespace

TriangleSoup read_stl(const std::string& path, double scale) {
  if (!(scale > 0.0) || !std::isfinite(scale)) {
    throw stl_error(path, fmt::format("the STL scale must be a positive number, got {}", scale));
  }
  TriangleSoup soup = parse_any(read_whole_file(path), path, scale);
  if (soup.empty()) {
    throw stl_error(path, "the STL file holds no triangle");
  }
  return soup;
}

}  // namespace partimix::geometry
