#pragma once
// The appended raw-binary block of a VTK XML file (particle frames, io/vtk_frame_writer.hpp;
// grid frames, io/vti_frame_writer.hpp): each array is described by a <DataArray> element with
// its offset into the block, and written there as a UInt64 byte count followed by its bytes,
// little-endian.
#include <cstdint>
#include <functional>
#include <ostream>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "particles/frame_array.hpp"

namespace partimix::io {

// One array of the appended block: how the XML describes it and how its bytes are written.
struct AppendedArray {
  std::string name;
  std::string_view type;  // the VTK type: "Float64", "Int32", "Int64"
  int components = 1;
  std::size_t tuples = 0;
  std::uint64_t bytes = 0;
  std::function<void(std::ostream&)> write;
};

// The array over `values`, which must outlive the writing.
template <class T>
AppendedArray raw_array(const std::string& name, std::string_view type, int components,
                        std::span<const T> values) {
  const char* data = reinterpret_cast<const char*>(values.data());
  const std::uint64_t bytes = values.size_bytes();
  return {name, type, components, values.size(), bytes, [data, bytes](std::ostream& out) {
            out.write(data, static_cast<std::streamsize>(bytes));
          }};
}

// Appends the frame arrays (particles/frame_array.hpp), each of `tuples` tuples (points or
// cells); std::invalid_argument naming the array when one does not hold components * tuples.
void add_frame_arrays(std::vector<AppendedArray>& arrays, std::span<const FrameArray> extra,
                      std::size_t tuples);

// Appends to `xml` the element `tag` with one <DataArray> per array, indented by `indent`;
// `offset` runs over the appended block (the count and the bytes of each array).
void describe_section(std::string& xml, std::string_view tag, std::string_view indent,
                      const std::vector<AppendedArray>& arrays, bool with_tuples,
                      std::uint64_t& offset);

// Writes the arrays into the appended block, in the order they were described.
void write_block(std::ostream& out, const std::vector<AppendedArray>& arrays);

}  // namespace partimix::io
