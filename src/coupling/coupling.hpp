#pragma once
// What joins two methods (DESIGN.md, "One run"): a coupling reads the state of one method and
// writes forces or sources into another's (CFD-DEM drag, void fraction and momentum exchange
// next), so that neither method knows the other. The Runner calls every coupling once per step
// of the run's clock, before the methods step, and saves its state in checkpoints.
#include "core/state_archive.hpp"

namespace partimix::coupling {

class Coupling {
 public:
  virtual ~Coupling() = default;
  // Exchanges what the coupled methods owe each other for the step [time, time + dt].
  virtual void exchange(double time, double dt) = 0;
  // The coupling's own state (averaging windows, lagged fields), for checkpoints.
  virtual void save(StateArchive& /*archive*/, const std::string& /*prefix*/) const {}
  virtual void restore(const StateArchive& /*archive*/, const std::string& /*prefix*/) {}
};

}  // namespace partimix::coupling
