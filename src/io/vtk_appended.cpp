#include "io/vtk_appended.hpp"

#include <iterator>
#include <stdexcept>

#include <fmt/format.h>

#include "io/xml_text.hpp"

namespace partimix::io {

void add_frame_arrays(std::vector<AppendedArray>& arrays, std::span<const FrameArray> extra,
                      std::size_t tuples) {
  for (const FrameArray& array : extra) {
    if (array.components < 1 ||
        array.values.size() != tuples * static_cast<std::size_t>(array.components)) {
      throw std::invalid_argument(
          fmt::format("frame array '{}' holds {} values, not {} components for {} tuples",
                      array.name, array.values.size(), array.components, tuples));
    }
    AppendedArray appended = raw_array(array.name, "Float64", array.components, array.values);
    appended.tuples = tuples;
    arrays.push_back(std::move(appended));
  }
}

void describe_section(std::string& xml, std::string_view tag, std::string_view indent,
                      const std::vector<AppendedArray>& arrays, bool with_tuples,
                      std::uint64_t& offset) {
  auto out = std::back_inserter(xml);
  fmt::format_to(out, "{}<{}>\n", indent, tag);
  for (const auto& array : arrays) {
    fmt::format_to(out, "{}  <DataArray type=\"{}\" Name=\"{}\" NumberOfComponents=\"{}\"", indent,
                   array.type, xml_attribute(array.name), array.components);
    if (with_tuples) {
      fmt::format_to(out, " NumberOfTuples=\"{}\"", array.tuples);
    }
    fmt::format_to(out, " format=\"appended\" offset=\"{}\"/>\n", offset);
    offset += sizeof(std::uint64_t) + array.bytes;
  }
  fmt::format_to(out, "{}</{}>\n", indent, tag);
}

void write_block(std::ostream& out, const std::vector<AppendedArray>& arrays) {
  for (const auto& array : arrays) {
    out.write(reinterpret_cast<const char*>(&array.bytes), sizeof(array.bytes));
    array.write(out);
  }
}

}  // namespace partimix::io
