#pragma once
// The surge front of a collapsing water column, Z = x / a against T = t sqrt(2 g / a) (column
// width a, height 2a): Martin, J. C. and Moyce, W. J. (1952), "Part IV. An experimental study of
// the collapse of liquid columns on a rigid horizontal plane", Phil. Trans. R. Soc. Lond. A 244,
// 312-324, figure 3, n^2 = 2, a = 2.25 in (values as digitised in the PySPH examples); for the
// dam-break tests of SPH and of the two-phase grid fluid.
#include <vector>

namespace partimix::testing_cases {

struct SurgePoint {
  double T;
  double Z;
};

inline const std::vector<SurgePoint> kMartinMoyce = {
    {0.832, 1.217}, {1.219, 1.474}, {1.997, 2.292}, {2.547, 2.995}};

}  // namespace partimix::testing_cases
