#pragma once
// A VTK XML file with an appended raw block read back strictly (our stand-in for ParaView): the
// tags of its header, its arrays by section, offsets that tile the appended block exactly, and
// every value decoded from the raw binary. For the frame writers' tests (.vtp and .vti).
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <map>
#include <regex>
#include <string>
#include <vector>

namespace partimix::test {

struct Tag {
  std::string name;
  std::map<std::string, std::string> attributes;
};

struct ArrayInfo {
  std::string section;  // FieldData, PointData, CellData, Points or Verts
  std::map<std::string, std::string> attributes;
};

// The frame split at the '_' that starts the appended block.
struct ParsedFrame {
  std::vector<Tag> tags;  // opening tags in file order
  std::vector<ArrayInfo> arrays;
  std::string block;  // appended block, without the closing tags
};

inline std::map<std::string, std::string> parse_attributes(const std::string& text) {
  static const std::regex attribute(R"re(([A-Za-z_]+)="([^"]*)")re");
  std::map<std::string, std::string> attributes;
  for (std::sregex_iterator it(text.begin(), text.end(), attribute), end; it != end; ++it) {
    attributes[(*it)[1]] = (*it)[2];
  }
  return attributes;
}

inline void parse_header(const std::string& header, ParsedFrame& frame) {
  static const std::regex tag(R"re(<(/?)([A-Za-z]+)([^>]*)>)re");
  std::string section;
  for (std::sregex_iterator it(header.begin(), header.end(), tag), end; it != end; ++it) {
    const std::string name = (*it)[2];
    if ((*it)[1] == "/")
      continue;
    Tag parsed{name, parse_attributes((*it)[3])};
    if (name == "FieldData" || name == "PointData" || name == "CellData" || name == "Points" ||
        name == "Verts") {
      section = name;
    }
    if (name == "DataArray")
      frame.arrays.push_back({section, parsed.attributes});
    frame.tags.push_back(parsed);
  }
}

inline ParsedFrame parse_frame(const std::string& text) {
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

inline const Tag& find_tag(const ParsedFrame& frame, const std::string& name) {
  for (const auto& tag : frame.tags) {
    if (tag.name == name)
      return tag;
  }
  ADD_FAILURE() << "no <" << name << "> tag";
  static const Tag none;
  return none;
}

inline const ArrayInfo& find_array(const ParsedFrame& frame, const std::string& name) {
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

inline std::size_t type_size(const std::string& type) {
  if (type == "Float64" || type == "Int64")
    return 8;
  if (type == "Int32")
    return 4;
  ADD_FAILURE() << "unexpected type " << type;
  return 1;
}

// Each array's byte count must match its type, components and tuples, and the arrays must
// follow one another in the appended block with no gap and nothing after the last.
inline void expect_offsets_tile_block(const ParsedFrame& frame, std::size_t points) {
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

}  // namespace partimix::test
