#pragma once
// A per-particle array that a method computes for its frames only, beside the store's output
// fields (Solver::frame_arrays): `components` doubles per particle, particle after particle, as
// VTK reads a point array. DEM's grain shapes for ParaView's glyphs are such arrays (docs/dem.md,
// "Drawing superquadric grains in ParaView"). The values belong to the solver and stay valid
// until its next step or call of frame_arrays().
#include <span>
#include <string>

namespace partimix {

struct FrameArray {
  std::string name;
  int components = 1;
  std::span<const double> values;  // components * particles
};

}  // namespace partimix
