#pragma once
// The truck drum's walls as closed triangle meshes in the drum's frame (docs/truck-drum.md,
// "Meshes and the STL export"): the shell as the solid of revolution of its meridian polygon
// (the head disc, the three lateral parts between their rings, the opening disc; its lateral
// faces are exact along the generators, chords around the turn), and each blade as the closed
// strip swept along its curve (the four corners of its cross-section at each station, end caps).
// Each mesh is closed and consistently wound, as geometry::TriangleMesh needs; write_stl writes
// any of them for ParaView or a CAD viewer.
#include <ostream>

#include "geometry/stl_reader.hpp"
#include "geometry/truck_drum.hpp"

namespace partimix::geometry {

// Whether the shell's mesh closes the opening with a disc (a closed mesh, a Shape) or leaves it
// open (the contact surface, through which the material leaves).
enum class Opening { closed, open };

// `divisions` points around each ring (at least 3).
TriangleSoup truck_drum_shell_mesh(const TruckDrumGeometry& drum, int divisions,
                                   Opening opening = Opening::closed);
// The most stations a blade's mesh may have (a bound on the memory and time of a strange input).
inline constexpr int kMostBladeStations = 200000;

// Blade `blade` (0 or 1, half a turn apart) of segment `segment`, with a station wherever its
// angle has turned by 2 π / divisions or by t_b / (2 h_b), the smaller (at least 2 stations);
// each side between stations as four triangles about the quad's centre; throws
// std::invalid_argument past kMostBladeStations. The blade reaches from
// r(z) - h_b to r(z) + root_depth: a root depth above zero sinks its outer face into the wall
// behind the shell, so that a grain at the shell never meets it.
TriangleSoup truck_drum_blade_mesh(const TruckDrumGeometry& drum, int segment, int blade,
                                   int divisions, double root_depth = 0.0);
// The contact surface of the drum (docs/truck-drum.md, "As a wall"): the shell open at the
// opening and the six blades, each sunk by its thickness into the wall behind the shell.
TriangleSoup truck_drum_surface_mesh(const TruckDrumGeometry& drum, int divisions);
// Binary STL (float coordinates) onto `out`; the caller checks the stream.
void write_stl(std::ostream& out, const TriangleSoup& triangles);

}  // namespace partimix::geometry
