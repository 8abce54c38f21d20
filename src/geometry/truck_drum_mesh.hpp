#pragma once
// The truck drum's walls as closed triangle meshes in the drum's frame (docs/truck-drum.md,
// "Meshes and the STL export"): the shell as the solid of revolution of its meridian polygon
// (the head disc, the three lateral parts between their rings, the opening disc; its lateral
// faces are exact along the generators, chords around the turn), and each blade as the closed
// strip swept along its curve (the four corners of its cross-section at each station, end caps).
// Each mesh is closed and consistently wound, as geometry::TriangleMesh needs; write_stl writes
// any of them for ParaView or a CAD viewer.
#include <string>

#include "geometry/stl_reader.hpp"
#include "geometry/truck_drum.hpp"

namespace partimix::geometry {

// `divisions` points around each ring (at least 3).
TriangleSoup truck_drum_shell_mesh(const TruckDrumGeometry& drum, int divisions);
// Blade `blade` (0 or 1, half a turn apart) of segment `segment`, with a station wherever its
// angle has turned by 2 π / divisions or by t_b / (2 h_b), the smaller (at least 2 stations);
// each side between stations as four triangles about the quad's centre.
TriangleSoup truck_drum_blade_mesh(const TruckDrumGeometry& drum, int segment, int blade,
                                   int divisions);
// Binary STL; throws std::runtime_error naming the file when it cannot be written.
void write_stl(const std::string& path, const TriangleSoup& triangles);

}  // namespace partimix::geometry
