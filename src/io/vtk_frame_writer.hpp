#pragma once
// One output frame as a VTK XML PolyData file (.vtp) that ParaView opens: the particles are the
// points, each a vertex cell, and every particle field marked for output is a point array named
// after the field. The frame's time is the field-data array TimeValue. Arrays are stored as raw
// little-endian binary in an appended block, so writing costs about one pass over the fields.
// A method's frame arrays (Solver::frame_arrays) follow the fields as Float64 point arrays.
#include <filesystem>
#include <span>

#include "particles/frame_array.hpp"
#include "particles/particle_store.hpp"

namespace partimix::io {

// Writes the frame to "<file>.tmp" and renames it to file, so a frame is never half-written.
// Throws RunError naming the file on any I/O failure.
// Each extra array must hold components * store.size() values (std::invalid_argument if not).
void write_vtp_frame(const std::filesystem::path& file, const ParticleStore& store, double time,
                     std::span<const FrameArray> extra = {});

}  // namespace partimix::io
