#pragma once
// Johnson-Cook constants of two metals for the tests (docs/multi-material-sph.md, "Johnson-Cook
// strength and damage"): strength from Johnson & Cook 1983, fracture from Johnson & Cook 1985.
#include "materials/johnson_cook.hpp"

namespace partimix::test_support {

constexpr double kRoom = 294.0;  // T_room [K], our choice; the papers give T_melt

// OFHC copper: strength constants of Johnson & Cook 1983, fracture constants of Johnson & Cook
// 1985.
inline materials::JohnsonCookParameters ofhc_copper() {
  materials::JohnsonCookParameters p;
  p.A = 90.0e6;
  p.B = 292.0e6;
  p.n = 0.31;
  p.C = 0.025;
  p.m = 1.09;
  p.reference_strain_rate = 1.0;
  p.room_temperature = kRoom;
  p.melt_temperature = 1356.0;
  p.D1 = 0.54;
  p.D2 = 4.89;
  p.D3 = -3.03;
  p.D4 = 0.014;
  p.D5 = 1.12;
  return p;
}

// 4340 steel, the same two sources.
inline materials::JohnsonCookParameters steel_4340() {
  materials::JohnsonCookParameters p;
  p.A = 792.0e6;
  p.B = 510.0e6;
  p.n = 0.26;
  p.C = 0.014;
  p.m = 1.03;
  p.reference_strain_rate = 1.0;
  p.room_temperature = kRoom;
  p.melt_temperature = 1793.0;
  p.D1 = 0.05;
  p.D2 = 3.44;
  p.D3 = -2.12;
  p.D4 = 0.002;
  p.D5 = 0.61;
  return p;
}

}  // namespace partimix::test_support
