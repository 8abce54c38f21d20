#pragma once
// Settings of the droplet analysis (docs/multi-material-sph.md, "The scheme", droplet
// measurements; docs/case-reference.md, "analyses"): which materials of sph.materials are the
// shell and the gas, and the rupture's link distance. Apart from the analysis so that
// AnalysisOptions and the case's AnalysisSpec can hold it.
#include <vector>

namespace partimix::analysis {

struct DropletOptions {
  int shell = -1;              // the shell's index in sph.materials (the particles' field material)
  std::vector<int> gas;        // the gas materials' indices
  double link = 0.0;           // [m]: damaged shell particles this close join a rupture's path
  double after_rupture = 0.1;  // [s]: the summary's second pressure, this long after the rupture
  int dimensions = 3;          // 2: areas and discs; 3: volumes and spheres
};

}  // namespace partimix::analysis
