#pragma once
// Text for XML attribute values (the VTK and .pvd writers): escapes the five characters that
// XML reserves so that any field name or file name gives a well-formed file.
#include <string>
#include <string_view>

namespace partimix::io {

std::string xml_attribute(std::string_view text);

}  // namespace partimix::io
