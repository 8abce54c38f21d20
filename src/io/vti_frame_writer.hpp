#pragma once
// The frame of a method on a grid as a VTK XML ImageData file (.vti) that ParaView opens: the
// grid's cells with one cell array per frame array, the frame's time as the field-data array
// TimeValue, raw little-endian binary in an appended block (io/vtk_appended.hpp).
#include <filesystem>

#include "particles/grid_frame.hpp"

namespace partimix::io {

// Writes the frame to "<file>.tmp" and renames it to file, so a frame is never half-written.
// Throws RunError naming the file on any I/O failure, std::invalid_argument when an array does
// not hold components * cells values.
void write_vti_frame(const std::filesystem::path& file, const GridFrame& frame, double time);

}  // namespace partimix::io
