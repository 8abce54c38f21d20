#pragma once
// What joins two methods (DESIGN.md, "One run"): a coupling reads the state of one method and
// writes forces or sources into another's (CFD-DEM: void fraction, drag and momentum exchange),
// so that neither method knows the other. The Runner calls every coupling once per step of the
// run's clock before the methods step (`exchange`), and again before each method takes its
// steps (`before_method`, with the method's index in the case's `solver`), so that a coupling
// can hand a method what another method has just computed; it saves its state in checkpoints.
#include <cstddef>
#include <map>
#include <string>

#include "core/state_archive.hpp"

namespace partimix::coupling {

class Coupling {
 public:
  virtual ~Coupling() = default;
  // Exchanges what the coupled methods owe each other for the step [time, time + dt].
  virtual void exchange(double /*time*/, double /*dt*/) {}
  // Before method `m` takes its steps over [time, time + dt] (after the methods before it in
  // `solver` have taken theirs).
  virtual void before_method(std::size_t /*m*/, double /*time*/, double /*dt*/) {}
  // Figures the coupling derived from the case (its kernel's width), for run.json and the
  // console, by name with their unit.
  virtual std::map<std::string, double> derived_parameters() const { return {}; }
  // The coupling's own state (averaging windows, lagged fields), for checkpoints.
  virtual void save(StateArchive& /*archive*/, const std::string& /*prefix*/) const {}
  virtual void restore(const StateArchive& /*archive*/, const std::string& /*prefix*/) {}
};

}  // namespace partimix::coupling
