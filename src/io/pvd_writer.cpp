#include "io/pvd_writer.hpp"

#include <fmt/format.h>

#include <iterator>
#include <ostream>
#include <utility>

#include "io/atomic_file.hpp"
#include "io/xml_text.hpp"

namespace partimix::io {

PvdWriter::PvdWriter(std::filesystem::path file, std::vector<PvdEntry> entries)
    : file_(std::move(file)), entries_(std::move(entries)) {}

void PvdWriter::add(double time, const std::string& relative_frame_path) {
  entries_.push_back({time, relative_frame_path});
  write();
}

void PvdWriter::write() const {
  std::string xml =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"Collection\" version=\"1.0\" byte_order=\"LittleEndian\">\n"
      "  <Collection>\n";
  for (const auto& entry : entries_) {
    fmt::format_to(std::back_inserter(xml),
                   "    <DataSet timestep=\"{}\" group=\"\" part=\"0\" file=\"{}\"/>\n", entry.time,
                   xml_attribute(entry.path));
  }
  xml +=
      "  </Collection>\n"
      "</VTKFile>\n";
  write_atomically(file_, [&xml](std::ostream& out) { out << xml; });
}

}  // namespace partimix::io
