#pragma once
// Ghia, Ghia & Shin (1982, J. Comput. Phys. 48, 387), the lid-driven cavity at Re = 100: their
// Tables I and II at the points inside the cavity, for the SPH and the grid fluid's cavity
// tests.
#include <array>

namespace partimix::test_support {

struct GhiaPoint {
  double position;  // y for u, x for v [L]
  double velocity;  // [U]
};

// Table I, Re = 100: u at x = 0.5 (the wall points y = 0 and 1 left out).
inline constexpr std::array<GhiaPoint, 15> kGhiaU{{{0.9766, 0.84123},
                                                   {0.9688, 0.78871},
                                                   {0.9609, 0.73722},
                                                   {0.9531, 0.68717},
                                                   {0.8516, 0.23151},
                                                   {0.7344, 0.00332},
                                                   {0.6172, -0.13641},
                                                   {0.5000, -0.20581},
                                                   {0.4531, -0.21090},
                                                   {0.2813, -0.15662},
                                                   {0.1719, -0.10150},
                                                   {0.1016, -0.06434},
                                                   {0.0703, -0.04775},
                                                   {0.0625, -0.04192},
                                                   {0.0547, -0.03717}}};

// Table II, Re = 100: v at y = 0.5.
inline constexpr std::array<GhiaPoint, 15> kGhiaV{{{0.9688, -0.05906},
                                                   {0.9609, -0.07391},
                                                   {0.9531, -0.08864},
                                                   {0.9453, -0.10313},
                                                   {0.9063, -0.16914},
                                                   {0.8594, -0.22445},
                                                   {0.8047, -0.24533},
                                                   {0.5000, 0.05454},
                                                   {0.2344, 0.17527},
                                                   {0.2266, 0.17507},
                                                   {0.1563, 0.16077},
                                                   {0.0938, 0.12317},
                                                   {0.0781, 0.10890},
                                                   {0.0703, 0.10091},
                                                   {0.0625, 0.09233}}};

}  // namespace partimix::test_support
